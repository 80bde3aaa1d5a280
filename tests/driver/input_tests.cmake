# Driver tests of input validation (label "driver"), run like those of tests.cmake (which defines
# signorini_add_driver_test() and ${decks}; this file is included after it): each case is the
# valid deck good.xml with --set overrides, checked with --check where the check can see the defect.

# A segment that is both a Dirichlet and a Neumann segment: the Dirichlet condition replaced the
# load there without a word. Refused when every component is fixed (Dirichlet Segments, or both
# Dirichlet X and Y Segments); for a roller a warning where the traction's fixed component is not 0
# on its edges; a traction on the roller's free component is valid.
signorini_add_driver_test(dirichlet_and_neumann_same_segment EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Neumann Segments=clamped" --set "Problem/Neumann Data=1"
       ${decks}/good.xml
  REGEX "Problem/Neumann Segments and Problem/Dirichlet Segments name the same segment 'clamped': the Dirichlet condition fixes u there")
set(elasticity --set "Problem/Type=plane strain elasticity" --set "Problem/Initial Velocity=0" --set "Problem/Obstacle="
               --set "Problem/Contact Segments=" --set "Problem/Dirichlet Segments=")
signorini_add_driver_test(roller_and_neumann_on_fixed_component EXIT 0
  ARGS --check --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped"
       --set "Problem/Neumann Segments=clamped" --set "Problem/Neumann Data=1, 0.5" ${decks}/good.xml
  REGEX "warning: .*Problem/Neumann Data's x component is not 0 on edges where Problem/Dirichlet X Segments hold u_x = 0: that part of the load has no effect there")
# A traction whose fixed component is 0 on the roller's edges (not a constant 0) is valid.
signorini_add_driver_test(roller_and_neumann_zero_on_the_roller EXIT 0
  ARGS --check --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped"
       --set "Problem/Neumann Segments=clamped" --set "Problem/Neumann Data=x > 0.5 ? 1 : 0, 0.5" ${decks}/good.xml
  REGEX "good[.]xml is valid")
signorini_add_driver_test(rollers_both_components_and_neumann EXIT 1
  ARGS --check --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped"
       --set "Problem/Dirichlet Y Segments=clamped" --set "Problem/Neumann Segments=clamped"
       --set "Problem/Neumann Data=0, 1" ${decks}/good.xml
  REGEX "Problem/Neumann Segments names the segment 'clamped', which Problem/Dirichlet X Segments and Dirichlet Y Segments both name: every component of u is fixed there")
signorini_add_driver_test(roller_and_neumann_on_free_component EXIT 0
  ARGS --check --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped"
       --set "Problem/Neumann Segments=clamped" --set "Problem/Neumann Data=0, 1" ${decks}/good.xml
  REGEX "good[.]xml is valid")

# Neumann Data without Neumann Segments is never applied: a warning, like the other keys without effect.
signorini_add_driver_test(neumann_data_without_segments EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Neumann Data=1" ${decks}/good.xml
  REGEX "warning: .*good[.]xml: no Problem/Neumann Segments; without effect: Problem/Neumann Data\n"
        "good[.]xml is valid")

# muParser's "=" assigns: "x=1 ? 0 : -1" set x to 0 for the rest of the evaluation and gave 0
# everywhere. Refused in every expression, naming the key; the comparisons ==, <=, >=, != stay valid.
signorini_add_driver_test(expression_assignment EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Initial Velocity=x=1 ? 0 : -1" ${decks}/good.xml
  REGEX "Problem/Initial Velocity: expression 'x=1 [?] 0 : -1' contains '=', which assigns to a variable [(]muParser's assignment operator[)]; write '==' to compare")
signorini_add_driver_test(expression_assignment_in_obstacle EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=(y=0.5)*0 + sin(pi*y) - 1.05" ${decks}/good.xml
  REGEX "Problem/Obstacle: expression '[(]y=0[.]5[)][*]0 [+] sin[(]pi[*]y[)] - 1[.]05' contains '='")
signorini_add_driver_test(expression_comparisons_valid EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Initial Velocity=x==1 ? 0 : (x<=0) + (x>=2) + (y!=3) - 1" ${decks}/good.xml
  REGEX "good[.]xml is valid")

# A basename that makes a file name longer than the file system allows (NAME_MAX, 255 here) is
# refused by --check, naming Output/Basename; the longest name is the step table's ".part" file
# (".steps.csv.part", 15 characters) without adaptivity, ".cycle<l>.steps.csv.part" with it.
# 240 characters fit without adaptivity (the run writes its files), not with two cycles.
string(REPEAT "a" 240 long240)
signorini_add_driver_test(basename_longest_that_fits EXIT 0
  ARGS --output-dir {OUT} --set "Output/Basename=${long240}" ${decks}/good.xml
  REGEX "good[.]xml done: 4 steps"
  FILES ${long240}.steps.csv ${long240}.e)
signorini_add_driver_test(basename_too_long_adaptive EXIT 1
  ARGS --check --output-dir {OUT} --set "Output/Basename=${long240}" --set "Adaptivity/Strategy=uniform"
       --set "Adaptivity/Cycles=2" ${decks}/good.xml
  REGEX "Output/Basename 'a+[.][.][.]' [(]240 characters[)] is too long: with the suffix '[.]cycle0[.]steps[.]csv[.]part' of the run's files a file name has 262 characters, more than the 255 the file system allows")
signorini_add_driver_test(basename_too_long EXIT 1
  ARGS --check --output-dir {OUT} --set "Output/Basename=${long240}aaaaaaaaaaaa" ${decks}/good.xml
  REGEX "Output/Basename 'a+[.][.][.]' [(]252 characters[)] is too long: with the suffix '[.]steps[.]csv[.]part'")
string(REPEAT "d" 300 long300)
signorini_add_driver_test(output_dir_name_too_long EXIT 1
  ARGS --check --output-dir {OUT}/missing/${long300} ${decks}/good.xml
  REGEX "--output-dir '[^']*/missing/d+': the folder name 'd+[.][.][.]' has 300 characters, more than the 255 the file system allows")
# An output file that cannot be created says why (here: its ".part" name is taken by a directory).
signorini_add_driver_test(output_create_error_gives_reason EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "cannot create output file '[^']*good[.]steps[.]csv[.]part': Is a directory"
  BLOCK good.steps.csv.part)

# Lists of segment names and segment specifications: a name given twice, an empty item (two commas
# in a row, a comma at the end) and a segment without a name were accepted (the empty items
# skipped silently); each is an error naming the key.
signorini_add_driver_test(segment_list_repeated_name EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Dirichlet Segments=clamped, clamped" ${decks}/good.xml
  REGEX "Problem/Dirichlet Segments: the segment 'clamped' is named twice in 'clamped, clamped'")
signorini_add_driver_test(segment_list_empty_item EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Dirichlet Segments=clamped,,contact" ${decks}/good.xml
  REGEX "Problem/Dirichlet Segments: empty item in the list 'clamped,,contact'")
signorini_add_driver_test(segment_list_trailing_comma EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Contact Segments=contact," ${decks}/good.xml
  REGEX "Problem/Contact Segments: empty item in the list 'contact,'")
signorini_add_driver_test(boundary_segment_trailing_comma EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/clamped=left," ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/clamped: empty condition in 'left,'")
signorini_add_driver_test(boundary_segment_empty_name EXIT 1
  ARGS --check --output-dir {OUT} ${decks}/boundary-segment-empty-name.xml
  REGEX "Mesh/Boundary Segments: a segment with an empty name [(]'left'[)], which no list can name")
signorini_add_driver_test(output_exodus_create_error_gives_reason EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "cannot create Exodus II output file '[^']*good[.]e[.]part' [(]for '[^']*good[.]e'[)]: Is a directory"
  BLOCK good.e.part)

# Rectangles that doubles cannot represent: vertices closer than the coordinates' resolution gave
# Ifpack2's "Inf or NaN" as an unexpected error, extents of 1e200 a Cholesky pivot of -nan.
signorini_add_driver_test(rectangle_cells_below_resolution EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/X0=1e16" --set "Mesh/X1=10000000000000004"
       --set "Mesh/Refinement Level=3" ${decks}/good.xml
  REGEX "Mesh/X0, X1, Y0, Y1, Cells X, Cells Y, Refinement Level: cells of .* at coordinates of 1e[+]16 are below 1e-10 of them")
signorini_add_driver_test(rectangle_beyond_1e100 EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/X1=1e200" ${decks}/good.xml
  REGEX "Mesh/X1 = 1e[+]200: beyond 1e100 in magnitude")

# Poisson's ratio near 1/2: a warning at set-up, and a solve that stops short names the cause.
# On 578 unknowns CG + Jacobi needs 16 iterations per step at nu = 0.3 and 34-36 at nu = 0.4999, the
# initial projection fewer than 25.
signorini_add_driver_test(poisson_ratio_near_half_warns EXIT 0
  ARGS --check --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped"
       --set "Problem/Poisson's Ratio=0.4999" ${decks}/good.xml
  REGEX "warning: .*Problem/Poisson's Ratio = 0[.]4999 is close to 1/2 [(]lambda / mu = 4999[)]: bilinear elements lock")
signorini_add_driver_test(poisson_ratio_near_half_names_the_cause_of_a_failing_solve EXIT 1
  ARGS --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped" --set "Mesh/Refinement Level=2"
       --set "Problem/Initial Velocity=x*y, -x*y" --set "Problem/Poisson's Ratio=0.4999"
       --set "Linear Solver/Preconditioner=Jacobi" --set "Linear Solver/Maximum Iterations=25" ${decks}/good.xml
  REGEX "solver failure: step 1 [(]t = 0[.]0025[)]: linear solver CG [+] Jacobi for the step matrix A = M [+] beta k\\^2 K did not reach the relative tolerance 1e-10 in 25 iterations [(]Linear Solver/Maximum Iterations[)]; Problem/Poisson's Ratio = 0[.]4999 is close to 1/2")
signorini_add_driver_test(poisson_ratio_0_3_solves_within_25_iterations EXIT 0
  ARGS --output-dir {OUT} ${elasticity} --set "Problem/Dirichlet X Segments=clamped" --set "Mesh/Refinement Level=2"
       --set "Problem/Initial Velocity=x*y, -x*y" --set "Problem/Poisson's Ratio=0.3"
       --set "Linear Solver/Preconditioner=Jacobi" --set "Linear Solver/Maximum Iterations=25" ${decks}/good.xml
  REGEX "good[.]xml done: 4 steps" FILES good.e good.steps.csv)

# Data that stop being finite numbers later in the run are found at set-up, so by --check too (it
# sampled them at t = 0 only, and the run stopped in that step). The earliest time wins, here in the
# upper half of the mesh (the other rank's cells on 2 ranks) before the lower half turns NaN.
signorini_add_driver_test(check_finds_body_force_infinite_later_in_the_run EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Body Force=y > 0.6 && t > 0.004 ? 1/(x-x) : (t > 0.008 ? sqrt(-1) : 0)"
       ${decks}/good.xml
  REGEX "Problem/Body Force: .* evaluates to inf at [(][0-9.]+, 0[.][6-9][0-9]*[)], t = 0[.]005 [(]step 2 of the run[)]")
signorini_add_driver_test(check_finds_obstacle_not_a_number_later_in_the_run EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=t > 0.006 ? sqrt(-1) : sin(pi*y) - 1.05" ${decks}/good.xml
  REGEX "Problem/Obstacle: .* evaluates to nan at [(]1, [0-9.]+[)], t = 0[.]0075 on the contact boundary [(]step 3 of the run[)]")
# A million steps: every 4th step is sampled (2e7 samples per rank at most), then the three skipped
# before the first hit, so the step named is the earliest (500002, not the sampled 500005).
signorini_add_driver_test(check_names_the_earliest_step_between_sampled_ones EXIT 1
  ARGS --check --output-dir {OUT} --set "Time Integration/Time Step=1e-8"
       --set "Problem/Body Force=t > 0.0050000125 ? sqrt(-1) : 0" ${decks}/good.xml
  REGEX "Problem/Body Force: .* evaluates to nan at [(][0-9.]+, [0-9.]+[)], t = 0[.]00500002 [(]step 500002 of the run[)]")
