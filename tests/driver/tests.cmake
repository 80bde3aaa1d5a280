# End-to-end tests of the signorini driver on bad input (label "driver").
# Each case runs `signorini` on 2 MPI ranks through run_bad_deck.cmake, which checks the exit
# status of EVERY rank, the message (regular expressions) and that the output directory is left
# empty (or holds exactly the expected files). The decks in driver/decks are copies of the tiny
# valid deck good.xml with ONE defect each (see the comment at the top of each file).
set(SIGNORINI_DRIVER_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
set(SIGNORINI_DRIVER_DECKS ${CMAKE_CURRENT_LIST_DIR}/decks)

# signorini_add_driver_test(NAME EXIT <status>|nonzero ARGS <signorini args>...
#                           [REGEX <re>...] [FILES <file>...] [BLOCK <name>...] [SEED <file>...]
#                           [UNCHANGED <file>...] [NP n])
# ARGS may use {OUT} for the test's fresh output directory. Every REGEX (each one argument, ";"
# included) must match stdout+stderr;
# FILES are the only files allowed (and required) in the output directory afterwards; BLOCK names
# directories made there before the run, so that writing an output of that name fails; SEED names
# files made there before the run (an earlier run's outputs), UNCHANGED those that must be left
# exactly as they were.
function(signorini_add_driver_test name)
  # PARSE_ARGV keeps a ";" inside one argument (escaped as "\;"): a message such as "X = Jacobi;
  # without effect: Y" stays one regular expression instead of two matched apart.
  cmake_parse_arguments(PARSE_ARGV 1 D "" "EXIT;NP" "ARGS;REGEX;ABSENT;FILES;BLOCK;SEED;UNCHANGED")
  if(NOT D_NP)
    set(D_NP 2)
  endif()
  string(REPLACE ";" "|" args "${D_ARGS}")
  string(REPLACE "\\;" "<SEMICOLON>" regex "${D_REGEX}")
  string(REPLACE ";" "<AND>" regex "${regex}")
  string(REPLACE ";" "<AND>" absent "${D_ABSENT}")
  string(REPLACE ";" "|" files "${D_FILES}")
  string(REPLACE ";" "|" block "${D_BLOCK}")
  string(REPLACE ";" "|" seed "${D_SEED}")
  string(REPLACE ";" "|" unchanged "${D_UNCHANGED}")
  add_test(NAME driver_${name}
    COMMAND ${CMAKE_COMMAND}
      "-DSIGNORINI=$<TARGET_FILE:signorini>"
      "-DMPIEXEC=${SIGNORINI_MPIEXEC}"
      "-DNP=${D_NP}"
      "-DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/driver/${name}"
      "-DWRAPPER=${SIGNORINI_DRIVER_TEST_DIR}/rank_status.sh"
      "-DARGS=${args}"
      "-DEXPECT_EXIT=${D_EXIT}"
      "-DEXPECT_REGEX=${regex}"
      "-DABSENT_REGEX=${absent}"
      "-DEXPECT_FILES=${files}"
      "-DBLOCK=${block}"
      "-DSEED=${seed}"
      "-DUNCHANGED=${unchanged}"
      -DTIMEOUT=50
      -P ${SIGNORINI_DRIVER_TEST_DIR}/run_bad_deck.cmake)
  set_tests_properties(driver_${name} PROPERTIES TIMEOUT 60 PROCESSORS ${D_NP} LABELS driver)
endfunction()

# A bad deck: exit status 1 on every rank, the message, nothing written. ARGN would split a regular
# expression at a ";" into two matched apart: such a message takes signorini_add_driver_test.
function(signorini_add_bad_deck_test name deck)
  cmake_parse_arguments(PARSE_ARGV 2 B "" "" "")
  if("${B_UNPARSED_ARGUMENTS}" MATCHES "\\\\;")
    message(FATAL_ERROR "driver_${name}: a regular expression with ';': use signorini_add_driver_test")
  endif()
  signorini_add_driver_test(${name} EXIT 1 ARGS --output-dir {OUT} ${deck} REGEX ${ARGN})
endfunction()

set(decks ${SIGNORINI_DRIVER_DECKS})

# Controls: the base deck (and its Exodus variant) are valid, so each bad deck fails because of
# its one defect.
signorini_add_driver_test(good_deck EXIT 0
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "good[.]xml done: 4 steps"
  FILES good.steps.csv good.e)
signorini_add_driver_test(good_exodus_deck EXIT 0
  ARGS --output-dir {OUT} ${decks}/good-exodus.xml
  REGEX "good-exodus[.]xml done: 4 steps"
  FILES good-exodus.steps.csv good-exodus.e)

# Adaptive runs that stop on total unknowns or on the tolerance before their planned cycles: the
# cycle that ends the run is written under the final names like the last planned cycle (Exodus
# included), the earlier cycles' Exodus files only on request. Uniform refinement of the 4 x 4
# deck: 9 x 9 nodes in each of the 4 steps of cycle 1 = 324 >= 300; any estimate is below 1e30.
signorini_add_driver_test(adaptive_stop_on_total_unknowns EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=300"
       ${decks}/good.xml
  REGEX "cycle 1: total unknowns 324," "good[.]xml done: 4 steps, 81 unknowns per step"
        "cycle 1 ends the run: its total unknowns reach Adaptivity/Maximum Total Unknowns"
        "wrote [^ ]*/good[.]cycle0[.]steps[.]csv"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
# At the boundary of the rule: Maximum Total Unknowns equal to cycle 1's total (4 steps x 81 nodes)
# ends the run there ("reach": at or above).
signorini_add_driver_test(adaptive_stop_on_total_unknowns_reached_exactly EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=324"
       --set "Adaptivity/Cycles=3" ${decks}/good.xml
  REGEX "cycle 1: total unknowns 324,"
        "cycle 1 ends the run: its total unknowns reach Adaptivity/Maximum Total Unknowns"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
signorini_add_driver_test(adaptive_stop_on_total_unknowns_all_cycles EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=300"
       --set "Adaptivity/Write All Cycles=true" ${decks}/good.xml
  REGEX "cycle 1: total unknowns 324," "wrote [^ ]*/good[.]cycle0[.]steps[.]csv" "wrote [^ ]*/good[.]cycle0[.]e"
  FILES good.cycle0.steps.csv good.cycle0.e good.steps.csv good.e good.cycles.csv)
# Unknowns Limit = do not exceed: cycle 2 (4 steps x 17 x 17 nodes = 1156) is not run under a limit
# of 1000 (cycle 1's results become the run's), runs under a limit of 1156 and ends the run there
# ("reach"), and a limit below cycle 0's 4 x 25 = 100 is refused before anything runs.
signorini_add_driver_test(adaptive_unknowns_not_exceeded EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=1000"
       --set "Adaptivity/Unknowns Limit=do not exceed" --set "Adaptivity/Cycles=3" ${decks}/good.xml
  REGEX "the run ends with cycle 1: cycle 2 would have 1156 total unknowns, above Adaptivity/Maximum Total Unknowns = 1000 [(]Unknowns Limit = do not exceed[)]"
        "good[.]xml done: 4 steps, 81 unknowns per step"
  ABSENT "cycle 2: total unknowns"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
signorini_add_driver_test(adaptive_unknowns_not_exceeded_at_the_limit EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=1156"
       --set "Adaptivity/Unknowns Limit=do not exceed" --set "Adaptivity/Cycles=4" ${decks}/good.xml
  REGEX "cycle 2: total unknowns 1156,"
        "cycle 2 ends the run: its total unknowns reach Adaptivity/Maximum Total Unknowns"
  FILES good.cycle0.steps.csv good.cycle1.steps.csv good.steps.csv good.e good.cycles.csv)
signorini_add_driver_test(adaptive_unknowns_limit_below_cycle0 EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=99"
       --set "Adaptivity/Unknowns Limit=do not exceed" ${decks}/good.xml
  REGEX "Adaptivity/Maximum Total Unknowns = 99 with Unknowns Limit = do not exceed: cycle 0 alone, 4 steps on the deck's mesh of 25 unknowns, has 100 total unknowns")
signorini_add_driver_test(unknowns_limit_without_limit EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=2"
       --set "Adaptivity/Unknowns Limit=do not exceed" ${decks}/good.xml
  REGEX "warning: [^ ]*good[.]xml: Adaptivity/Maximum Total Unknowns = 0 [(]no limit[)][^\n]*without effect: Adaptivity/Unknowns Limit"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
# A cycle whose energy rises above its initial energy although nothing supplies energy is reported:
# the disc of a user study, dropped at 1 m/s, has 1/2 rho |D| v^2 = 30.81 J/m (|D| the area of its
# 128-gon, 7.8508e-3 m^2) and gains energy in cycle 1 where a refined step meets the penetration
# the coarse segments allowed; with Contact Zone Gap the energy stays at its initial value, no warning.
signorini_add_driver_test(energy_gain_warned EXIT 0
  ARGS --output-dir {OUT} ${decks}/disc-drop.xml
  REGEX "warning: cycle 1: the Newmark energy [(]newmark_energy[)] reaches [0-9.]+ in step [0-9]+ [(]t = [^)]+[)], [0-9.]+% above its initial 30[.]81, although no load, body force or moving obstacle supplies energy"
        "Adaptivity/Contact Zone Gap refines the contact zone before the first contact"
  ABSENT "cycle 0: the energy" "slopes across"
  FILES disc-drop.cycle0.steps.csv disc-drop.steps.csv disc-drop.cycles.csv)
signorini_add_driver_test(energy_gain_none_with_contact_zone_gap EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Contact Zone Gap=1e-5" ${decks}/disc-drop.xml
  REGEX "cycle 1: total unknowns"
  ABSENT "the Newmark energy [(]newmark_energy[)] reaches"
  FILES disc-drop.cycle0.steps.csv disc-drop.steps.csv disc-drop.cycles.csv)
# An elastic deck's obstacle that slopes across Contact Direction (the disc on a 10 degree slope)
# draws a warning: the contact force acts along the direction, not normal to the slope; 4 degrees
# (below the 5 degree threshold) and the flat floor do not.
signorini_add_driver_test(obstacle_slope_warned EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=-0.05/cos(10*_pi/180) - 2e-5 + x*tan(10*_pi/180) - y" ${decks}/disc-drop.xml
  REGEX "warning: [^ ]*disc-drop[.]xml: the obstacle's surface under the contact boundary [(]y [+] Problem/Obstacle[)] slopes across Contact Direction by up to 10 degrees [(]slope 0[.]176 near"
        "the contact force acts along Contact Direction, not normal to the obstacle")
signorini_add_driver_test(obstacle_slope_below_the_threshold EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=-0.05/cos(4*_pi/180) - 2e-5 + x*tan(4*_pi/180) - y" ${decks}/disc-drop.xml
  ABSENT "slopes across")
# The flat floor written through x on the disc's circle, y0 - (-sqrt(R^2 - x^2)): g depends on x, the
# surface the boundary meets does not (a review's case drew 66 degrees when g's own slope was taken).
signorini_add_driver_test(obstacle_slope_of_the_surface_not_of_g EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=-0.05 - 2e-5 + sqrt(max(0, 0.0025 - x^2))" ${decks}/disc-drop.xml
  ABSENT "slopes across")
# The wall of block-into-wall.xml (Contact Direction -x, g = -0.0005 - 2 (y - 0.025)^2): its surface
# x - g slopes by 4 |y - 0.025| <= 0.1 (5.71 degrees) at the block's corners (secants over eighths of
# the deck's edges: 5.53).
signorini_add_driver_test(obstacle_slope_of_a_curved_wall EXIT 0
  ARGS --check --output-dir {OUT} ${decks}/block-into-wall.xml
  REGEX "[(]x - Problem/Obstacle[)] slopes across Contact Direction by up to 5[.][5-7][0-9]* degrees")
signorini_add_driver_test(adaptive_stop_on_tolerance EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Tolerance=1e30"
       --set "Adaptivity/Write All Cycles=true" ${decks}/good.xml
  REGEX "cycle 0: total unknowns 100," "good[.]xml done: 4 steps, 25 unknowns per step"
        "cycle 0 ends the run: its estimate is at or below Adaptivity/Tolerance"
  FILES good.steps.csv good.e good.cycles.csv)

# Reading the deck.
signorini_add_bad_deck_test(malformed_xml ${decks}/malformed.xml
  "malformed[.]xml: malformed XML deck: XML parse error at line 19")
# A segment condition with < inside a value: the message says how XML writes it.
signorini_add_bad_deck_test(less_than_in_value ${decks}/less-than-in-value.xml
  "less-than-in-value[.]xml: malformed XML deck: XML parse error at line 18: invalid character in attribute value [(]inside a value write < as &lt. and & as &amp.")
signorini_add_bad_deck_test(missing_deck ${decks}/does-not-exist.xml
  "does-not-exist[.]xml: cannot open the deck"
  "missing or unreadable file")
# Decks are UTF-8: other bytes (Latin-1 from an old editor) would reach the Exodus records as they are.
signorini_add_driver_test(deck_not_utf8 EXIT 1 ARGS --output-dir {OUT} ${decks}/not-utf8.xml
  REGEX "not-utf8[.]xml: line 1 is not UTF-8 [(]byte 0xe9[)]; save the deck as UTF-8")
# A type Teuchos has no converter for: its message named neither the entry nor the line.
signorini_add_bad_deck_test(unknown_parameter_type ${decks}/unknown-type.xml
  "unknown-type[.]xml: 'Mesh/Cells X' has the type \"integer\", which is not a parameter type [(]int, double, bool or string[)]")
signorini_add_bad_deck_test(duplicate_key ${decks}/duplicate-key.xml
  "duplicate-key[.]xml: 'Time Integration/Final Time' is given twice")
signorini_add_bad_deck_test(directory_as_deck ${decks}
  "decks: is a directory, not a deck")

signorini_add_driver_test(hidden_basename_from_deck_name EXIT 1 ARGS --output-dir {OUT} ${decks}/.hidden.xml
  REGEX "the deck's file name '.*/[.]hidden[.]xml' gives the output basename '[.]hidden' [(]hidden or empty files[)]; set Output/Basename")
# Validation against Simulation::getValidParameters().
signorini_add_bad_deck_test(unknown_key ${decks}/unknown-key.xml
  "unknown-key[.]xml: unknown parameter 'Time Stepp' in sublist 'Time Integration'"
  "did you mean 'Time Step'")
# Bools: Teuchos' own message names neither the key nor the line.
signorini_add_bad_deck_test(bad_bool ${decks}/bad-bool.xml
  "bad-bool[.]xml: 'Output/Write Exodus' = \"MAYBE\" is not a bool [(]true or false[)]")
signorini_add_bad_deck_test(missing_type ${decks}/missing-type.xml
  "missing-type[.]xml: 'Time Integration/Time Step' has no type attribute")
# true/false, yes/no, 1/0 in any case with blanks around, in a deck and in --set alike.
signorini_add_driver_test(bool_words_in_deck EXIT 0
  ARGS --output-dir {OUT} ${decks}/bool-words.xml
  FILES bool-words.steps.csv)
signorini_add_driver_test(bool_words_in_set EXIT 0
  ARGS --output-dir {OUT} --set "Output/Write Exodus= No " --set "Estimator/Compute S1=YES" ${decks}/good.xml
  FILES good.steps.csv)
signorini_add_bad_deck_test(wrong_type ${decks}/wrong-type.xml
  "wrong-type[.]xml: 'Time Integration/Time Step' has type string but must be double")
signorini_add_bad_deck_test(zero_time_step ${decks}/zero-time-step.xml
  "zero-time-step[.]xml: 'Time Integration/Time Step' = 0 is not allowed")
signorini_add_bad_deck_test(negative_time_step ${decks}/negative-time-step.xml
  "negative-time-step[.]xml: 'Time Integration/Time Step' = -0[.]0025 is not allowed")
# beta k^2 below the normal doubles made the step matrix A = M + beta k^2 K and the acceleration
# (u - u~) / (beta k^2) meaningless: the run failed in its second step without naming the key.
signorini_add_driver_test(time_step_below_normal_doubles EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Time Step=1e-160" --set "Time Integration/Final Time=4e-160"
       ${decks}/good.xml
  REGEX "'Time Integration/Time Step' = 1e-160 is not allowed")
# A value that is not a number of the declared type ("0.01s") must not be read as 0.01 silently.
signorini_add_bad_deck_test(unparsable_number ${decks}/unparsable-number.xml
  "error: .*unparsable-number[.]xml: 'Time Integration/Final Time' = \"0[.]01s\" is not a number")
# An int is accepted for a double, and must then be range-checked like one (not crash).
signorini_add_bad_deck_test(int_out_of_range_for_double ${decks}/int-out-of-range-for-double.xml
  "int-out-of-range-for-double[.]xml: 'Time Integration/Alpha' = 3 is not allowed")

# Newmark: 2 beta >= alpha >= 1/2.
signorini_add_bad_deck_test(newmark_alpha_too_small ${decks}/alpha-too-small.xml
  "Time Integration/Alpha = 0[.]4 violates 2 Beta >= Alpha >= 1/2")
signorini_add_bad_deck_test(newmark_beta_too_small ${decks}/beta-too-small.xml
  "Time Integration/Beta = 0[.]2 violates 2 Beta >= Alpha >= 1/2")
# The implicit contact force is Deuflhard, Krause and Ertel's trapezoidal step: other Alpha or Beta are refused.
signorini_add_driver_test(newmark_implicit_contact_needs_trapezoidal EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Contact Force=implicit" ${decks}/good.xml
  REGEX "Time Integration/Contact Force = implicit needs Alpha = 1/2 and Beta = 1/4 .*not Alpha = 0[.]5 and Beta = 0[.]5")

# Boundary segments naming a side set the mesh does not have.
signorini_add_bad_deck_test(missing_side_set ${decks}/missing-side-set.xml
  "Mesh/Boundary Segments/contact: side set 'rigth' does not exist"
  "its side sets: bottom, left, right, top")
signorini_add_bad_deck_test(exodus_missing_side_set ${decks}/exodus-missing-side-set.xml
  "Mesh/Boundary Segments/contact: side set 'east' does not exist in .*unit-square-4x4[.]exo"
  "its side sets: bottom, left, right, top")

# Two side sets in one segment: the second is named as such, not as a condition without x or y.
signorini_add_driver_test(two_side_sets_in_one_segment EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/contact=right, top" ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/contact: 'top' is a second side set; a segment is one side set followed by conditions on x or y")
signorini_add_driver_test(segment_condition_without_coordinate EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/contact=right, z > 0" ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/contact: condition 'z > 0' must start with x or y [(]a segment is \"<side set>")

signorini_add_bad_deck_test(exodus_missing_file ${decks}/exodus-missing-file.xml
  "Mesh/File: Exodus II mesh file '[^']*no-such-mesh[.]exo' does not exist")

# Problem set-up.
signorini_add_bad_deck_test(unknown_segment_name ${decks}/unknown-segment-name.xml
  "Problem/Contact Segments: no boundary segment named 'contakt'"
  "did you mean 'contact'")
# The other problem type's material, or the other mesh type's keys, would be ignored: a wrong
# material or mesh without a word (Stiffness given for an elastic body ran with E = 1).
signorini_add_driver_test(material_of_the_other_problem_type EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Young's Modulus=5" ${decks}/good.xml
  REGEX "Problem/Young's Modulus: applies to Type = plane strain elasticity only [(]the scalar wave's material is Problem/Stiffness[)]")
signorini_add_driver_test(stiffness_for_elasticity EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Type=plane strain elasticity" --set "Problem/Stiffness=73e9"
       --set "Problem/Initial Velocity=0, -sin(pi*x/2)" ${decks}/good.xml
  REGEX "Problem/Stiffness: applies to Type = scalar wave only")
signorini_add_driver_test(rectangle_keys_on_exodus_mesh EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Cells X=7" --set "Mesh/X1=5" ${decks}/good-exodus.xml
  REGEX "Mesh/(X1, Mesh/Cells X|Cells X, Mesh/X1): applies to Type = rectangle only [(]the Exodus file gives the mesh[)]; remove them from the deck or set them to their defaults")
signorini_add_driver_test(exodus_file_on_rectangle EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/File=mesh.exo" ${decks}/good.xml
  REGEX "Mesh/File: applies to Type = exodus only")
# A boundary condition on a segment that selects no boundary edge (a unit slip: "x >= 3" on a unit
# square) would leave the body unclamped or unloaded; each kind of segment, with its key.
signorini_add_driver_test(dirichlet_segment_without_edges EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Boundary Segments/clamped=left, y > 5" ${decks}/good.xml
  REGEX "Problem/Dirichlet Segments: the segment 'clamped' contains no boundary edge of the mesh")
signorini_add_driver_test(neumann_segment_without_edges EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Boundary Segments/load=top, x >= 3" --set "Problem/Neumann Segments=load"
       --set "Problem/Neumann Data=1" ${decks}/good.xml
  REGEX "Problem/Neumann Segments: the segment 'load' contains no boundary edge of the mesh")
# A segment narrower than an edge ([0.6, 0.65] holds the midpoint of the edge [0.5, 0.75], of
# neither of its halves) would lose its edges on the next cycle's mesh: refused at set-up (the run
# used to go on without the load from cycle 1 on).
signorini_add_driver_test(segment_without_edges_on_a_refined_mesh EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Boundary Segments/load=top, x >= 0.6, x <= 0.65" --set "Problem/Neumann Segments=load"
       --set "Problem/Neumann Data=1" --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=2"
       --set "Output/Write Exodus=false" ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/load: holds boundary edges on the deck's mesh but none on the meshes refined 1 level[(]s[)] further")
# An exact solution that is not a finite number where the errors are measured.
signorini_add_driver_test(exact_solution_not_finite EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Exact Solution=sqrt(x - 2)" ${decks}/good.xml
  REGEX "Problem/Exact Solution: 'sqrt[(]x - 2[)]' evaluates to nan at")
signorini_add_driver_test(initial_penetration EXIT 1 ARGS --output-dir {OUT} ${decks}/penetrating.xml
  REGEX "Problem/Initial Displacement penetrates the obstacle at t = 0 on [0-9]+ of [0-9]+ contact segments: the deepest, the mean gap on the segment at [(][^)]*[)], is -[0-9.e-]+; .*lift it there by at least that much")
# Several segments penetrate: the deepest is named (lifting the first named one by its gap was not
# enough), with the count.
signorini_add_driver_test(initial_penetration_deepest EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Obstacle=0.01 - 0.2*(y-0.5)^2" --set "Mesh/Refinement Level=2" ${decks}/good.xml
  REGEX "penetrates the obstacle at t = 0 on 4 of 8 contact segments: the deepest, the mean gap on the segment at [(]1, 0[.](4375|5625)[)], is -0[.]00895833")
# An obstacle that is not a finite number at a node of the contact boundary (finite at every Gauss
# point): the estimator's s1 takes it there, and its CG failed without naming the obstacle.
signorini_add_driver_test(obstacle_not_finite_at_a_node EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=-0.03 + 0.0001/abs(y-0.5)" ${decks}/good.xml
  REGEX "Problem/Obstacle: '-0[.]03 [+] 0[.]0001/abs[(]y-0[.]5[)]' evaluates to inf at [(]1, 0[.]5[)], t = 0 on the contact boundary")
signorini_add_driver_test(obstacle_not_finite_at_a_node_later EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=(t < 0.005) ? -0.03 : -0.03 + 0.0001/abs(y-0.5)" ${decks}/good.xml
  REGEX "Problem/Obstacle: .* evaluates to inf at [(]1, 0[.]5[)], t = 0[.]005 on the contact boundary [(]step 2 of the run[)]")
# A penetration that the deck's segments average away but the finer segments of a later adaptive
# cycle show: refused at set-up (it used to stop the run at the start of cycle 1); the same deck
# with one cycle runs (the control).
set(wavy_obstacle --set "Problem/Obstacle=0.01*sin(4*pi*y) - 0.002" --set "Adaptivity/Strategy=uniform")
signorini_add_driver_test(initial_penetration_on_finer_segments EXIT 1
  ARGS --output-dir {OUT} ${wavy_obstacle} --set "Adaptivity/Cycles=3" ${decks}/good.xml
  REGEX "Problem/Initial Displacement penetrates the obstacle at t = 0 on the finer meshes that Adaptivity/Cycles = 3 can make: the mean gap on the deepest contact segment, of 2 edge[(]s[)] of length 0[.]0625 at [(]1, 0[.][0-9]+[)], would be -0[.]0043")
signorini_add_driver_test(initial_penetration_on_finer_segments_control EXIT 0
  ARGS --check --output-dir {OUT} ${wavy_obstacle} --set "Adaptivity/Cycles=1" ${decks}/good.xml
  REGEX "good[.]xml is valid")
# A Dirichlet segment narrower than the edges of the next cycle's meshes: it would vanish there and
# change the problem (it used to, silently); refused at set-up, and valid with one cycle.
set(narrow_clamp --set "Mesh/Boundary Segments/clamped=left, y >= 0.6, y <= 0.65" --set "Adaptivity/Strategy=uniform")
signorini_add_driver_test(segment_vanishes_on_finer_meshes EXIT 1
  ARGS --check --output-dir {OUT} ${narrow_clamp} --set "Adaptivity/Cycles=2" ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/clamped: holds boundary edges on the deck's mesh but none on the meshes refined 1 level[(]s[)] further, which Adaptivity/Cycles = 2 can make")
signorini_add_driver_test(segment_vanishes_on_finer_meshes_control EXIT 0
  ARGS --check --output-dir {OUT} ${narrow_clamp} --set "Adaptivity/Cycles=1" ${decks}/good.xml
  REGEX "good[.]xml is valid")
signorini_add_bad_deck_test(bad_expression ${decks}/bad-expression.xml
  "Problem/Obstacle: cannot parse expression 'sin[(]pi[*]y - 1[.]05'")

# Output directory that cannot be created or written (the test's own output directory, also
# the working directory, must stay empty).
signorini_add_driver_test(unwritable_output_dir_under_file EXIT 1
  ARGS --output-dir /dev/null/out ${decks}/good.xml
  REGEX "--output-dir: cannot write to '/dev/null/out' [(]Not a directory[)]")
signorini_add_driver_test(unwritable_output_directory_key EXIT 1
  ARGS --set "Output/Directory=/dev/null/out" ${decks}/good.xml
  REGEX "Output/Directory: cannot write to '/dev/null/out'")
signorini_add_driver_test(unwritable_output_dir_in_proc EXIT 1
  ARGS --output-dir /proc/signorini-not-writable ${decks}/good.xml
  REGEX "--output-dir: cannot write to '/proc/signorini-not-writable' [(]no file can be created in '/proc/': [A-Z][a-z]")

# --set overrides are validated like the deck.
signorini_add_driver_test(set_unknown_key EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Time Stp=0.001" ${decks}/good.xml
  REGEX "--set 'Time Integration/Time Stp=0[.]001': unknown parameter 'Time Stp'"
        "did you mean 'Time Step'")
# A key given without its sublist: the message names the sublist that has it.
signorini_add_driver_test(set_key_without_sublist EXIT 1
  ARGS --output-dir {OUT} --set "Refinement Level=3" ${decks}/good.xml
  REGEX "--set 'Refinement Level=3': unknown parameter 'Refinement Level' at the top level [(]did you mean 'Mesh/Refinement Level'[?][)]")
signorini_add_driver_test(set_bad_double EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Time Step=fast" ${decks}/good.xml
  REGEX "--set 'Time Integration/Time Step=fast': 'fast' is not a valid double")

# Bad usage: exit status 2.
signorini_add_driver_test(usage_no_deck EXIT 2
  REGEX "signorini: no deck given" "usage: signorini")
signorini_add_driver_test(usage_unknown_option EXIT 2
  ARGS --bogus ${decks}/good.xml
  REGEX "unknown option --bogus" "usage: signorini")
# A single dash is a typo of an option, not a deck (the next deck used to run in full, writing results).
signorini_add_driver_test(usage_single_dash_option EXIT 2
  ARGS --output-dir {OUT} -check ${decks}/good.xml
  REGEX "unknown option -check [(]did you mean --check[?][)]" "given as [.]/-check or after --")
signorini_add_driver_test(usage_set_empty_key EXIT 2
  ARGS --output-dir {OUT} --set "Mesh/=3" ${decks}/good.xml
  REGEX "--set 'Mesh/=3': expected 'Sublist/key=value'")
signorini_add_driver_test(usage_option_without_value EXIT 2
  ARGS --output-dir
  REGEX "--output-dir needs a value")
signorini_add_driver_test(usage_set_without_value EXIT 2
  ARGS --set "Mesh/Refinement Level" ${decks}/good.xml
  REGEX "--set 'Mesh/Refinement Level': expected 'Sublist/key=value'")
# An option given twice: the last one wins (scripts add overrides to a command), with a warning
# naming both.
signorini_add_driver_test(set_repeated_last_wins EXIT 0
  ARGS --check --output-dir {OUT} --set "Time Integration/Final Time=0.0025" --set "Problem/Density=2"
       --set "Time Integration/Final Time=0.005" ${decks}/good.xml
  REGEX "warning: --set 'Time Integration/Final Time=0[.]005' replaces the earlier --set 'Time Integration/Final Time=0[.]0025'"
        "2 steps of k = 0[.]0025 to T = 0[.]005")
signorini_add_driver_test(output_dir_repeated_last_wins EXIT 0
  ARGS --check --output-dir {OUT}/first --output-dir {OUT}/second ${decks}/good.xml
  REGEX "warning: --output-dir '[^']*/out/second' replaces the earlier --output-dir '[^']*/out/first'"
        "output: [^ ]*/out/second/good[.][*]")

# --help and -h print our usage and nothing before it (Kokkos used to answer them with its own
# options first); Kokkos' options still pass through to Kokkos.
signorini_add_driver_test(usage_help EXIT 0
  ARGS --help
  REGEX "^usage: signorini [[]options[]]")
signorini_add_driver_test(usage_kokkos_help EXIT 0
  ARGS --kokkos-help
  REGEX "Kokkos command line arguments")
signorini_add_driver_test(usage_help_short_with_kokkos_option EXIT 0
  ARGS --kokkos-disable-warnings -h
  REGEX "^usage: signorini [[]options[]]")
# --version: signorini's version and the libraries it was built with, before any
# deck is read (also with other options around it).
signorini_add_driver_test(version EXIT 0
  ARGS --set "Output/Basename=x" --version ${decks}/good.xml
  REGEX "^signorini [0-9]+[.][0-9]+[.][0-9]+\nTrilinos [0-9.]+ [(]Kokkos devices:[ A-Za-z]+[)], p4est [0-9.]+, MPI: [A-Za-z]")

# Batches: a failing deck does not stop the others, but the exit status says something failed.
signorini_add_driver_test(batch_bad_then_good EXIT 1
  ARGS --output-dir {OUT} ${decks}/unknown-key.xml ${decks}/good.xml
  REGEX "unknown parameter 'Time Stepp'"
        "good[.]xml done: 4 steps"
        "1 of 2 deck[(]s[)] failed"
  FILES good.steps.csv good.e)
# Two decks of one batch with the same output base: the second is refused before it replaces the
# first's results (here the same deck twice).
signorini_add_driver_test(batch_same_output_base EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml ${decks}/../decks/good.xml
  REGEX "good[.]xml: writes to the output base '.*/good' of the batch's deck .*good[.]xml, whose results it would replace"
        "1 of 2 deck[(]s[)] failed"
  FILES good.steps.csv good.e)
# The same with a relative output folder that the first deck creates (the base was compared
# relative before the folder existed and absolute after).
signorini_add_driver_test(batch_same_relative_new_output_base EXIT 1
  ARGS --output-dir new ${decks}/good.xml ${decks}/good.xml
  REGEX "good[.]xml: writes to the output base 'new/good' of the batch's deck .*good[.]xml, whose results it would replace"
        "1 of 2 deck[(]s[)] failed"
  FILES new/good.steps.csv new/good.e)
signorini_add_driver_test(batch_good_then_bad EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml ${decks}/penetrating.xml
  REGEX "good[.]xml done: 4 steps"
        "Problem/Initial Displacement penetrates the obstacle"
        "1 of 2 deck[(]s[)] failed"
  FILES good.steps.csv good.e)

# A body held by nothing but the contact, at a time step 1e10 times its Courant limit: the step
# matrix is not positive definite to rounding. Where it fails first depends on the stiffness: the
# strip's factorisation (on rank 0 alone: the other rank used to wait for it forever), Belos' CG, or
# the contact QP, whose message named H = h on a deck with H = 2h. Each says what to change.
set(floating --set Adaptivity/Strategy=none --set "Problem/Initial Velocity=0,0" --set "Problem/Body Force=0,-100"
    --set Problem/Obstacle=0 --set "Time Integration/Time Step=1e4" --set "Time Integration/Final Time=1e5")
signorini_add_driver_test(floating_body_strip_factorisation EXIT 1
  ARGS --output-dir {OUT} ${floating} --set "Problem/Young's Modulus=1e4" --set Problem/Density=1 ${decks}/rigid-drop.xml
  REGEX "solver failure: the contact Schur preconditioner [(]the step matrix on a strip along Gamma_C.*not positive definite.*lower Time Integration/Time Step")
# (The lumped Schur preconditioner: with the default, the coarse correction's approximation of the
# nearly singular matrix is caught first, below.)
signorini_add_driver_test(floating_body_cg_breakdown EXIT 1 NP 1  # on 2 ranks CG runs out of iterations instead
  ARGS --output-dir {OUT} ${floating} --set "Contact/Schur Preconditioner=lumped" ${decks}/rigid-drop.xml
  REGEX "solver failure: step 1 [(]t = 10000[)]: linear solver CG [+] MueLu for the step matrix .* broke down: .*non-positive.*lower Time Integration/Time Step")
# MueLu's Chebyshev smoother on graded trapezoids (a user study's bracket): with Ifpack2's default 10
# power iterations its eigenvalue estimate fell short and CG broke down in cycle 1; signorini's 20 hold.
# The control sets 10 again and is told what to change.
signorini_add_driver_test(muelu_chebyshev_on_graded_trapezoids EXIT 0 NP 1
  ARGS --output-dir {OUT} ${decks}/bracket-push.xml
  REGEX "cycle 1: total unknowns" FILES bracket-push.steps.csv bracket-push.cycle0.steps.csv bracket-push.cycles.csv)
# The Ritz projection's MueLu takes symmetric Gauss-Seidel, not the deck's smoother or its
# Chebyshev keys (which Ifpack2's relaxation refused at set-up).
signorini_add_driver_test(ritz_transfer_with_muelu EXIT 0 NP 1
  ARGS --output-dir {OUT} --set "Adaptivity/Transfer=Ritz projection"
       --set "Linear Solver/MueLu/smoother: params/chebyshev: eigenvalue max iterations=30" ${decks}/bracket-push.xml
  REGEX "cycle 1: total unknowns" FILES bracket-push.steps.csv bracket-push.cycle0.steps.csv bracket-push.cycles.csv)
# A deck that chooses another smoother gets no Chebyshev key (MueLu refused it: a set-up failure).
signorini_add_driver_test(muelu_relaxation_smoother EXIT 0 NP 1
  ARGS --output-dir {OUT} --set "Linear Solver/MueLu/smoother: type=RELAXATION" ${decks}/bracket-push.xml
  REGEX "cycle 1: total unknowns" FILES bracket-push.steps.csv bracket-push.cycle0.steps.csv bracket-push.cycles.csv)
signorini_add_driver_test(muelu_chebyshev_short_estimate EXIT 1 NP 1
  ARGS --output-dir {OUT} --set "Linear Solver/MueLu/smoother: params/chebyshev: eigenvalue max iterations=10"
       ${decks}/bracket-push.xml
  REGEX "cycle 1, step 4 .* broke down: .*non-positive.*MueLu's Chebyshev smoother is not when it underestimates the largest eigenvalue: raise 'Linear Solver/MueLu/smoother: params/chebyshev: eigenvalue max iterations' [(]signorini sets 20[)] or choose Linear Solver/Preconditioner = Jacobi")
# Transfers that move much energy: the L2 projection raises the strain energy of a cycle that
# resolves the waves poorly (a user study's bracket drop, coarser: +62% of its largest energy in
# cycle 1); the warning names the sum, its share and the cause. Cycle 0 keeps one mesh: no warning.
signorini_add_driver_test(transfer_energy_warning EXIT 0 NP 1
  ARGS --output-dir {OUT} ${decks}/bracket-drop.xml
  REGEX "warning: cycle 1: moving the state to each step's mesh raised its energy [(]kinetic [+] strain[)] by [0-9.]+ summed over the cycle's mesh changes that raised it [(][0-9.]+% of its largest energy [0-9.]+. net [+][0-9.]+ over its [0-9]+ mesh changes[)], so the cycle's dynamics are not the problem's: the L2 projection of u raises the strain energy"
  ABSENT "warning: cycle 0"
  FILES bracket-drop.steps.csv bracket-drop.cycle0.steps.csv bracket-drop.cycles.csv)
# The Ritz projection of u cannot raise the energy: the same run loses it instead (its solves with
# K + mu M of the free bracket by MueLu with symmetric Gauss-Seidel; with Chebyshev CG broke down).
signorini_add_driver_test(transfer_energy_warning_ritz EXIT 0 NP 1
  ARGS --output-dir {OUT} --set "Adaptivity/Transfer=Ritz projection" ${decks}/bracket-drop.xml
  REGEX "warning: cycle 1: moving the state to each step's mesh lowered its energy [(]kinetic [+] strain[)] by [0-9.]+ summed over the cycle's mesh changes that lowered it .* net -[0-9.]+ .* the coarser parts of the step meshes cannot hold the finer scales"
  ABSENT "raises"
  FILES bracket-drop.steps.csv bracket-drop.cycle0.steps.csv bracket-drop.cycles.csv)
# A Courant number so large that the strip's layer count overflowed int (and so the coarse correction
# was dropped without a word): the coarse correction's Schur approximation of the nearly singular
# matrix has a negative diagonal, named as such (it was "every node under it is a Dirichlet node").
signorini_add_driver_test(floating_body_schur_diagonal EXIT 1
  ARGS --output-dir {OUT} ${floating} ${decks}/rigid-drop.xml
  REGEX "solver failure: the contact Schur preconditioner [(]Contact/Schur Preconditioner[)] has the diagonal entry -[0-9.e-]+ at the segment around [(]0[.]01875, 0[)], not a positive number: the step matrix is singular or nearly so.*lower Time Integration/Time Step")
signorini_add_driver_test(floating_body_contact_qp EXIT 1
  ARGS --output-dir {OUT} ${floating} --set "Problem/Young's Modulus=100" --set Problem/Density=1 ${decks}/rigid-drop.xml
  REGEX "contact QP: the multipliers diverged .*Q_AA is singular or nearly so, or the A-solves are not accurate enough.*raise Contact/KKT Tolerance")

# A solver failure in the middle of the run (after steps 0 and 1 were written): every rank
# exits 1 and the partial outputs are removed.
signorini_add_driver_test(solver_failure_mid_run EXIT 1
  ARGS --output-dir {OUT} ${decks}/solver-failure.xml
  REGEX "step 1/4"
        "solver-failure[.]xml: solver failure: step [0-9]+ [(]t = [^)]*[)]: linear solver .* did not reach the relative tolerance")
signorini_add_driver_test(solver_failure_in_new_directory EXIT 1
  ARGS --output-dir {OUT}/new/deeper ${decks}/solver-failure.xml
  REGEX "solver-failure[.]xml: solver failure")
signorini_add_driver_test(adaptive_failure_in_new_directory EXIT 1
  ARGS --output-dir {OUT}/new --set "Adaptivity/Strategy=uniform" ${decks}/solver-failure.xml
  REGEX "solver-failure[.]xml: solver failure")

# Rerunning into a directory that holds an earlier run's results under the same base name: a run
# that fails leaves all of them as they were (its own files appear only when the whole run has
# succeeded), and a run that succeeds replaces them all, also the cycle tables and the Exodus
# series tail it does not write again; files of other bases are left alone.
signorini_add_driver_test(failed_rerun_keeps_earlier_results EXIT 1
  ARGS --output-dir {OUT} ${decks}/solver-failure.xml
  SEED solver-failure.steps.csv solver-failure.e solver-failure.e-s.0001 solver-failure.cycle0.steps.csv
       solver-failure.cycles.csv
  UNCHANGED solver-failure.steps.csv solver-failure.e solver-failure.e-s.0001 solver-failure.cycle0.steps.csv
            solver-failure.cycles.csv
  REGEX "solver-failure[.]xml: solver failure"
  FILES solver-failure.steps.csv solver-failure.e solver-failure.e-s.0001 solver-failure.cycle0.steps.csv
        solver-failure.cycles.csv)
signorini_add_driver_test(rerun_replaces_earlier_results EXIT 0
  ARGS --output-dir {OUT} ${decks}/good.xml
  SEED good.steps.csv good.e good.e-s.0003 good.cycle2.steps.csv good.cycle2.e good.cycles.csv other.steps.csv
       good.extra.csv
  UNCHANGED other.steps.csv good.extra.csv
  REGEX "good[.]xml done: 4 steps"
  FILES good.steps.csv good.e other.steps.csv good.extra.csv)
# Only the file names count as outputs, not the directories: an output directory whose name looks
# like an Exodus series file ("run.e-s.2") keeps the cycle tables of a run that may stop early.
signorini_add_driver_test(output_directory_named_like_a_series EXIT 0
  ARGS --output-dir {OUT}/run.e-s.2 --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Maximum Total Unknowns=300"
       ${decks}/good.xml
  REGEX "cycle 1: total unknowns 324,"
  FILES run.e-s.2/good.cycle0.steps.csv run.e-s.2/good.steps.csv run.e-s.2/good.e run.e-s.2/good.cycles.csv)

# A Final Time that is not a whole number of time steps (the run used to end at another time
# without a word): an error naming both keys and the time the run would end at.
signorini_add_driver_test(final_time_not_whole_steps EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Time Step=0.003" ${decks}/good.xml
  REGEX "Time Integration/Final Time = 0[.]01 is not a whole number of Time Steps 0[.]003"
        "the run would end at t = 0[.]009")

# --print-parameters: exit 0, every parameter with its full path, nothing written.
signorini_add_driver_test(print_parameters EXIT 0
  ARGS --print-parameters
  REGEX "Time Integration/Time Step : double = 0[.]0025"
        "Mesh/Boundary Segments/  [(]sublist[)]"
        "Output/Write Exodus : bool = true")

# An output that cannot be written (its name taken by a directory) is an error on every rank, at
# whatever point of the run it happens (rank 0 writes; the others used to wait for it), and the
# files the run had already finished (earlier cycles, the step table) are removed.
signorini_add_driver_test(output_exodus_not_creatable EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "cannot create Exodus II output file" BLOCK good.e.part)
signorini_add_driver_test(output_steps_not_renamable EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "cannot rename output file '.*good[.]steps[.]csv[.]part'" BLOCK good.steps.csv)
signorini_add_driver_test(adaptive_cycles_table_not_renamable EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=2" ${decks}/good.xml
  REGEX "cannot rename output file '.*good[.]cycles[.]csv[.]part'" BLOCK good.cycles.csv)
signorini_add_driver_test(adaptive_second_cycle_not_writable EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=3" ${decks}/good.xml
  REGEX "cannot create output file '.*good[.]cycle1[.]steps[.]csv[.]part'" BLOCK good.cycle1.steps.csv.part)

# Output names that would leave the output directory or hide the files, an empty directory (was
# the file system root), and an obstacle that is not a number on Gamma_C (contact was dropped
# silently: every comparison with NaN is false).
signorini_add_driver_test(bad_basename_with_folder EXIT 1
  ARGS --output-dir {OUT} --set "Output/Basename=sub/x" ${decks}/good.xml
  REGEX "Output/Basename 'sub/x': must be a plain file name")
signorini_add_driver_test(bad_basename_dot EXIT 1
  ARGS --output-dir {OUT} --set "Output/Basename=.." ${decks}/good.xml
  REGEX "Output/Basename '[.][.]': must be a plain file name")
signorini_add_driver_test(bad_empty_output_directory EXIT 1
  ARGS --set "Output/Directory=" ${decks}/good.xml
  REGEX "Output/Directory: empty")
signorini_add_driver_test(bad_obstacle_not_a_number EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Obstacle=sqrt(y - 2)" ${decks}/good.xml
  REGEX "Problem/Obstacle: 'sqrt[(]y - 2[)]' evaluates to nan at [(].* on the contact boundary")
# A constant that is not a number (no point to name): said to hold everywhere, "nan" without a sign.
signorini_add_driver_test(bad_obstacle_constant_not_a_number EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Obstacle=0/0" ${decks}/good.xml
  REGEX "Problem/Obstacle: expression '0/0' evaluates to nan [(]it depends on none of x, y, t: everywhere[)]")
# Probes: the point must parse and lie in the mesh; the name becomes a CSV header field.
signorini_add_driver_test(bad_probe_name_with_comma EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/a,b=0.5, 0.5" ${decks}/good.xml
  REGEX "Output/Probes/a,b: a probe's name is a CSV column header; it must not be blank or hold a comma")
string(REPEAT "p" 249 long_probe_name)
signorini_add_driver_test(bad_probe_name_too_long EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/${long_probe_name}=0.5, 0.5" ${decks}/good.xml
  REGEX "Output/Probes/p+[.][.][.]: a probe's name has at most 248 bytes [(]it has 249")
# With v probed, elasticity's longest column is "probe:<name>:v:x": two bytes fewer for the name.
string(REPEAT "p" 247 long_probe_name)
signorini_add_driver_test(bad_probe_name_too_long_for_velocity EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/${long_probe_name}=0.05, 0.01" --set "Output/Probe Fields=u, v"
       ${decks}/block-into-wall.xml
  REGEX "Output/Probes/p+[.][.][.]: a probe's name has at most 246 bytes [(]it has 247")
# A probe "p" with its velocity and a probe "p:v" would name one column twice.
signorini_add_driver_test(bad_probe_names_one_column EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/p=0.5, 0.5" --set "Output/Probes/p:v=0.25, 0.5"
       --set "Output/Probe Fields=u, v" ${decks}/good.xml
  REGEX "Output/Probes/p:v and Output/Probes/p both give the column 'probe:p:v'; rename one of them")
# With the stress probed, the longest column is "probe:<name>:von_mises".
string(REPEAT "p" 241 long_probe_name)
signorini_add_driver_test(bad_probe_name_too_long_for_stress EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/${long_probe_name}=0.05, 0.01" --set "Output/Probe Fields=u, sigma"
       ${decks}/block-into-wall.xml
  REGEX "Output/Probes/p+[.][.][.]: a probe's name has at most 240 bytes [(]it has 241")
signorini_add_driver_test(bad_probe_fields_unknown EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probe Fields=u, w" ${decks}/good.xml
  REGEX "Output/Probe Fields: \"w\" in \"u, w\" is not a field: list u, v, a or sigma, separated by commas")
signorini_add_driver_test(bad_probe_fields_trailing_comma EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probe Fields=u," ${decks}/good.xml
  REGEX "Output/Probe Fields: \"u,\" has an empty item: list u, v, a or sigma, separated by commas")
# A number with a stray exponent is no number (strtod would read "0.5e" as 0.5): it goes to the expression parser.
signorini_add_driver_test(bad_probe_number_typo EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/p=0.5e, 0.5" ${decks}/good.xml
  REGEX "Output/Probes/p [(]x[)]: cannot parse expression '0[.]5e'")
signorini_add_driver_test(bad_probe_fields_twice EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probe Fields=u, v,v" ${decks}/good.xml
  REGEX "Output/Probe Fields: \"v\" is listed twice in \"u, v,v\"")
signorini_add_driver_test(bad_probe_stress_of_membrane EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/p=0.5, 0.5" --set "Output/Probe Fields=u, sigma" ${decks}/good.xml
  REGEX "Output/Probe Fields: sigma is the stress of plane strain elasticity [(]Problem/Type[)]; the scalar wave has none")
signorini_add_driver_test(bad_probe_point EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/centre=0.5 0.5" ${decks}/good.xml
  REGEX "Output/Probes/centre: expected \"x, y\", got \"0[.]5 0[.]5\"")
# Coordinates may be constant expressions: the point is evaluated (here outside the mesh, as named).
signorini_add_driver_test(bad_probe_expression_outside_the_mesh EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/far=2*2.5, max(1, 2)/4" ${decks}/good.xml
  REGEX "Output/Probes/far: point [(]5, 0[.]5[)] is outside the mesh")
# --check names each probe's point as the run samples it: the expressions evaluated.
signorini_add_driver_test(check_names_probe_points EXIT 0
  ARGS --check --output-dir {OUT} --set "Output/Probes/mid=max(1, 2)/4, 1/8" ${decks}/good.xml
  REGEX "probes [(]u, points of the undeformed body[)]: mid at [(]0[.]5, 0[.]125[)]")
signorini_add_driver_test(bad_probe_point_function EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/p=0.5, t" ${decks}/good.xml
  REGEX "Output/Probes/p: \"0[.]5, t\": a probe's coordinates are numbers or constant expressions, not functions of x, y or t")
signorini_add_driver_test(bad_probe_not_a_number EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/p=nan, 0.5" ${decks}/good.xml
  REGEX "Output/Probes/p: \"nan, 0[.]5\" is not a point [(]a coordinate is not a finite number[)]")
signorini_add_driver_test(bad_probe_outside_the_mesh EXIT 1
  ARGS --output-dir {OUT} --set "Output/Probes/far=5, 0.5" ${decks}/good.xml
  REGEX "Output/Probes/far: point [(]5, 0[.]5[)] is outside the mesh, which lies in [[]0, 1[]] x [[]0, 1[]]"
  ABSENT "does not fill it")
# A point inside the mesh's bounding box but in no cell (the L-bracket's notch): the message says so.
signorini_add_driver_test(probe_in_a_notch EXIT 1
  ARGS --check --output-dir {OUT} --set "Output/Probes/notch=0.06, 0.06" ${decks}/bracket-push.xml
  REGEX "Output/Probes/notch: point [(]0[.]06, 0[.]06[)] is outside the mesh, which lies in [[]0, 0[.]1[]] x [[]0, 0[.]08[]] but does not fill it: the point is in no cell")
# Output/Moment Point: elasticity's moments are about it; a point as the probes take them.
signorini_add_driver_test(bad_moment_point_of_membrane EXIT 1
  ARGS --output-dir {OUT} --set "Output/Moment Point=0.5, 0.5" ${decks}/good.xml
  REGEX "Output/Moment Point: moments are reported for plane strain elasticity [(]Problem/Type[)]; the scalar wave equation has none")
signorini_add_driver_test(bad_moment_point EXIT 1
  ARGS --output-dir {OUT} --set "Output/Moment Point=0.1" ${decks}/block-on-floor.xml
  REGEX "Output/Moment Point: expected \"x, y\", got \"0[.]1\"")
signorini_add_driver_test(bad_moment_point_function EXIT 1
  ARGS --output-dir {OUT} --set "Output/Moment Point=x, 0" ${decks}/block-on-floor.xml
  REGEX "Output/Moment Point: \"x, 0\": the moment point's coordinates are numbers or constant expressions")
signorini_add_driver_test(check_names_moment_point EXIT 0
  ARGS --check --output-dir {OUT} --set "Output/Moment Point=0.1/2, 2*0.025" ${decks}/block-on-floor.xml
  REGEX "moments and angular momentum about [(]0[.]05, 0[.]05[)] [(]Output/Moment Point[)]")
# An adaptive run has no angular_momentum column: --check names the moments only.
signorini_add_driver_test(check_names_moment_point_adaptive EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Cycles=2" ${PROJECT_SOURCE_DIR}/inputs/bar.xml
  REGEX "moments about [(]0, 0[)] [(]Output/Moment Point[)]"
  ABSENT "angular momentum")
# The scalar problem takes the origin however it is written.
signorini_add_driver_test(moment_point_origin_of_membrane EXIT 0
  ARGS --check --output-dir {OUT} --set "Output/Moment Point=0,0.0" ${decks}/good.xml)
# A Dirichlet segment's name becomes a column only where there are several: one with a long name is fine.
string(REPEAT "a" 250 long_segment)
signorini_add_driver_test(long_name_of_the_only_support EXIT 0
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/${long_segment}=left"
       --set "Problem/Dirichlet Segments=${long_segment}" ${PROJECT_SOURCE_DIR}/inputs/bar.xml)
signorini_add_driver_test(bad_long_name_of_a_support EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/${long_segment}=left"
       --set "Mesh/Boundary Segments/top=top" --set "Problem/Dirichlet Segments=${long_segment}, top"
       ${PROJECT_SOURCE_DIR}/inputs/bar.xml
  REGEX "with several Dirichlet segments each names the step table's columns reaction:<segment>; a name must not hold")
# Output/Stress Region: an expression of x and y that holds a cell centre; elasticity's.
signorini_add_driver_test(bad_stress_region_nowhere EXIT 1
  ARGS --output-dir {OUT} --set "Output/Stress Region=x > 5" ${decks}/block-on-floor.xml
  REGEX "Output/Stress Region: \"x > 5\" is 0 at every cell centre of the deck's mesh")
signorini_add_driver_test(bad_stress_region_in_time EXIT 1
  ARGS --output-dir {OUT} --set "Output/Stress Region=t < 1" ${decks}/block-on-floor.xml
  REGEX "Output/Stress Region: \"t < 1\" depends on t")
signorini_add_driver_test(bad_stress_region_not_a_number EXIT 1
  ARGS --output-dir {OUT} --set "Output/Stress Region=sqrt(x - 0.05)" ${decks}/block-on-floor.xml
  REGEX "Output/Stress Region: 'sqrt[(]x - 0[.]05[)]' evaluates to nan at [(]0[.]003125, 0[.]003125[)]")
# Boundary segments that no Problem list names are free edges: a warning names them.
signorini_add_driver_test(unused_boundary_segment EXIT 0
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/spare=top" --set "Mesh/Boundary Segments/spare2=bottom"
       ${decks}/good.xml
  REGEX "warning: .*good[.]xml: Mesh/Boundary Segments 'spare', 'spare2' named by no Problem/Dirichlet, Dirichlet X, Dirichlet Y, Neumann or Contact Segments: free edges")
# A constant obstacle under an elastic contact boundary that is not straight across the contact
# direction takes the body's shape (a user study's arched base rested on all of it); a flat
# obstacle is a function of the coordinate. The block's flat floor draws no warning.
signorini_add_driver_test(constant_obstacle_under_a_bent_contact_boundary EXIT 0
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/side=right" --set "Problem/Contact Segments=floor, side"
       ${decks}/block-on-floor.xml
  REGEX "warning: .*Problem/Obstacle is the constant -0[.]0005 while the contact boundary is not straight across the contact direction [(]y from 0 to 0[.]05[)]: the constraint holds point by point, so the obstacle takes the body's shape; the flat obstacle at y = -0[.]0005 [(]that gap from the boundary's lowest point[)] is \"-0[.]0005 - y\"")
signorini_add_driver_test(constant_obstacle_under_a_flat_contact_boundary EXIT 0
  ARGS --check --output-dir {OUT} ${decks}/block-on-floor.xml
  ABSENT "warning")
# A time step in which the fastest wave crosses the body many times (a density in g/cm^3 with SI
# moduli): the steps resolve none of the waves.
signorini_add_driver_test(time_step_beyond_the_wave_crossing EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Density=2.77" ${decks}/block-on-floor.xml
  REGEX "warning: .*in one Time Step 1e-05 the fastest wave [(]speed 1[.]98e[+]05[)] crosses the body [(]diameter 0[.]112[)] 17[.]7 times")
# An adaptive run that ends above its tolerance says so.
signorini_add_driver_test(tolerance_not_reached EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=2" --set "Adaptivity/Tolerance=1e-12"
       --set "Output/Write Exodus=false" ${decks}/good.xml
  REGEX "the run ends with cycle 1 [(]Adaptivity/Cycles[)] at the estimate [0-9.e+-]+, above Adaptivity/Tolerance 1[.]0000e-12"
  FILES good.steps.csv good.cycle0.steps.csv good.cycles.csv)
# A parse error names the region's variables, x and y (t is refused above).
signorini_add_driver_test(bad_stress_region_parse EXIT 1
  ARGS --output-dir {OUT} --set "Output/Stress Region=x > z" ${decks}/block-on-floor.xml
  REGEX "Output/Stress Region: cannot parse expression 'x > z': .* [(]allowed variables: x, y[)]")
# A moment point's coordinate that does not parse: no variable is allowed.
signorini_add_driver_test(bad_moment_point_parse EXIT 1
  ARGS --output-dir {OUT} --set "Output/Moment Point=0.1, 2*q" ${decks}/block-on-floor.xml
  REGEX "Output/Moment Point [(]y[)]: cannot parse expression '2[*]q': .* [(]allowed variables: none, a coordinate is constant[)]")
# An out-of-range value: the message says what the key does (here how to write no Exodus file at all).
signorini_add_driver_test(bad_exodus_interval EXIT 1
  ARGS --check --output-dir {OUT} --set "Output/Exodus Interval=0" ${decks}/good.xml
  REGEX "'Output/Exodus Interval' = 0 is not allowed; it must be >= 1 [(]Output/Exodus Interval: Write every n-th step to Exodus [(]the first and last step always; no Exodus file: Write Exodus = false[)][)]")
signorini_add_driver_test(bad_stress_region_of_membrane EXIT 1
  ARGS --output-dir {OUT} --set "Output/Stress Region=x > 0.5" ${decks}/good.xml
  REGEX "Output/Stress Region: stresses are those of plane strain elasticity")
# The Exodus file cannot take its final name when the run ends: the step table goes too.
signorini_add_driver_test(output_exodus_not_renamable EXIT 1
  ARGS --output-dir {OUT} ${decks}/good.xml
  REGEX "cannot rename output file '.*good[.]e[.]part'" BLOCK good.e)

# Adaptivity settings that are valid one by one but cannot work together, and meshes that cannot
# fit (p4est used to abort in malloc, or a uniform run grew until memory ran out).
signorini_add_driver_test(adaptive_refinement_fraction_zero EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2"
       --set "Adaptivity/Refinement Fraction=0" ${decks}/good.xml
  REGEX "Adaptivity/Refinement Fraction = 0 refines no cell with Strategy = fixed fraction")
signorini_add_driver_test(adaptive_maximum_level_not_above_base EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=bulk" --set "Adaptivity/Cycles=2"
       --set "Mesh/Refinement Level=1" --set "Adaptivity/Maximum Level=1" ${decks}/good.xml
  REGEX "Adaptivity/Maximum Level = 1 is not above Mesh/Refinement Level = 1")
signorini_add_driver_test(adaptive_fractions_above_one EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2"
       --set "Adaptivity/Refinement Fraction=0.7" --set "Adaptivity/Coarsening Fraction=0.4" ${decks}/good.xml
  REGEX "Adaptivity/Coarsening Fraction = 0[.]4 with Refinement Fraction = 0[.]7: together more than all cells")
signorini_add_driver_test(adaptive_all_cycles_without_exodus EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Write All Cycles=true"
       --set "Output/Write Exodus=false" ${decks}/good.xml
  REGEX "Adaptivity/Write All Cycles = true needs Output/Write Exodus = true")
# A run without error (at rest, no load) marks nothing: the cycle after the first repeats it and
# ends the run (its files are the run's result) instead of repeating it up to Cycles.
signorini_add_driver_test(adaptive_nothing_marked_ends_the_run EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=4"
       --set "Problem/Initial Velocity=0" ${decks}/good.xml
  REGEX "cycle 1 is the last: the marking of cycle 0 left every step's mesh as it was [(]no cell marked: its cell indicators were all 0 at rounding level [(]Adaptivity/Zero Tolerance[)][)], so a further cycle would repeat it\n"
        "cycle 1: total unknowns"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
# The disc falls rigidly for 40 us, penetrating the floor inside coarse contact segments whose mean
# gap stays positive (no segment active): its estimate is s1 alone, which marking leaves out, and
# the message says so (a review took "no cell marked" beside an estimate of 4e-5 for a defect).
signorini_add_driver_test(adaptive_nothing_marked_estimate_s1 EXIT 0
  ARGS --output-dir {OUT} --set "Time Integration/Final Time=4e-5" --set "Problem/Obstacle=-0.05 - 2e-6 - y"
       --set "Adaptivity/Refinement Fraction=0.3" --set "Adaptivity/Cycles=3" ${decks}/disc-drop.xml
  REGEX "cycle 1 is the last: the marking of cycle 0 left every step's mesh as it was [(]no cell marked: its cell indicators were all 0 at rounding level [(]Adaptivity/Zero Tolerance[)]. its estimate [0-9.e-]+ was s1 alone, which marking leaves out"
  FILES disc-drop.cycle0.steps.csv disc-drop.steps.csv disc-drop.cycles.csv)
# Strategy = none ignores the Adaptivity and Estimator keys the deck sets: a warning names them,
# the run goes on; so does Compute S1 = false its tolerance.
signorini_add_driver_test(estimator_keys_without_strategy EXIT 0
  ARGS --output-dir {OUT} --set "Estimator/Scaling=step" ${decks}/good.xml
  REGEX "warning: .*Strategy = none runs one pass on the deck's mesh without the estimator; without effect: Estimator/Scaling\n"
  FILES good.steps.csv good.e)
signorini_add_driver_test(s1_tolerance_without_s1 EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Estimator/Compute S1=false"
       --set "Estimator/S1 Relative Tolerance=1e-4" ${decks}/good.xml
  REGEX "warning: .*Estimator/Compute S1 = false; without effect: Estimator/S1 Relative Tolerance\n")
# Contact Zone Gap needs an obstacle and a strategy that chooses cells: a warning otherwise.
signorini_add_driver_test(contact_zone_gap_without_obstacle EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Contact Zone Gap=0.1"
       --set "Problem/Obstacle=" --set "Problem/Contact Segments=" ${decks}/good.xml
  REGEX "warning: .*the deck has no obstacle [(]Problem/Obstacle[)]; without effect: Adaptivity/Contact Zone Gap\n")
signorini_add_driver_test(contact_zone_gap_with_uniform EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Contact Zone Gap=0.1" ${decks}/good.xml
  REGEX "warning: .*Strategy = uniform refines every cell; without effect: Adaptivity/Contact Zone Gap\n")
# Reproducible arithmetic orders sums by the nodes' coordinates: a mesh with nodes at one point (a
# slit) is refused with it (the contact strip stopped on an internal assertion) and taken without.
signorini_add_driver_test(reproducible_arithmetic_on_a_slit EXIT 1
  ARGS --check --output-dir {OUT} ${decks}/slit-reproducible.xml
  REGEX "slit-reproducible[.]xml: Parallel/Reproducible Arithmetic = true orders every sum by the nodes' coordinates, which cannot tell apart nodes at one point: .*slit[.]exo: vertices 2 and 10 are at one point [(]0[.]5, 0[)].*; or set Parallel/Reproducible Arithmetic = false\n")
signorini_add_driver_test(ordinary_arithmetic_on_a_slit EXIT 0
  ARGS --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=false" ${decks}/slit-reproducible.xml
  REGEX "warning: .*slit[.]exo: vertices 2 and 10 are at one point [(]0[.]5, 0[)]" "slit-reproducible[.]xml done: 20 steps"
  FILES slit-reproducible.cycle0.steps.csv slit-reproducible.steps.csv slit-reproducible.e slit-reproducible.e-s.0001
        slit-reproducible.cycles.csv)
signorini_add_driver_test(contact_zone_gap_in_the_plan EXIT 0
  ARGS --check --output-dir {OUT} ${decks}/block-into-wall.xml
  REGEX "Algorithm 5[.]1: 4 cycle[(]s[)], .*also refining where the contact boundary comes within 0[.]0001 of the obstacle [(]Contact Zone Gap[)]\n")
signorini_add_driver_test(adaptive_keys_without_strategy EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Cycles=3" --set "Adaptivity/Refinement Fraction=0.2" ${decks}/good.xml
  REGEX "warning: .*Strategy = none .*without effect: Adaptivity/(Cycles, Adaptivity/Refinement Fraction|Refinement Fraction, Adaptivity/Cycles)\n"
        "good[.]xml done: 4 steps"
  FILES good.steps.csv good.e)
# A run that may stop early (here on a tolerance) and whose next cycle would not fit into the memory
# (Parallel/Memory Per Rank: 20 kB) ends with the cycle before it, whose files become the run's
# (they were lost with the error).
signorini_add_driver_test(adaptive_stop_before_a_cycle_too_large EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=3" --set "Adaptivity/Tolerance=1e-30"
       --set "Parallel/Memory Per Rank=0.00002" ${decks}/good.xml
  REGEX "cycle 0: total unknowns 100," "warning: the run ends with cycle 0: Adaptivity: cycle 1 .* more than Parallel/Memory Per Rank"
        "good[.]xml done: 4 steps, 25 unknowns per step"
  FILES good.steps.csv good.e good.cycles.csv)
signorini_add_driver_test(mesh_larger_than_the_memory_per_rank EXIT 1
  ARGS --output-dir {OUT} --set "Parallel/Memory Per Rank=0.000001" ${decks}/good.xml
  REGEX "a mesh of 16 cells on 2 rank[(]s[)]: at least .* GB per rank, more than Parallel/Memory Per Rank = 1e-06 GB per rank")
# Strategy = uniform marks every cell and keeps one mesh per cycle: a warning names the marking
# and transfer keys the deck sets.
signorini_add_driver_test(adaptive_uniform_ignores_fractions EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=2"
       --set "Adaptivity/Refinement Fraction=0.2" --set "Adaptivity/Transfer=interpolation" ${decks}/good.xml
  REGEX "warning: .*Strategy = uniform refines every cell; without effect: Adaptivity/Refinement Fraction, Adaptivity/Transfer\n"
        "good[.]xml done: 4 steps"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
# Once every cell is at the Maximum Level, a further cycle would repeat the last: the run stops
# there (cycle 1 of 4) and says why; that cycle's files get the final names.
signorini_add_driver_test(adaptive_stops_at_maximum_level EXIT 0
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=4"
       --set "Adaptivity/Maximum Level=1" ${decks}/good.xml
  REGEX "cycle 1 is the last: every cell of every step is at Adaptivity/Maximum Level = 1"
        "cycle 1: total unknowns 324," "good[.]xml done: 4 steps"
  FILES good.cycle0.steps.csv good.steps.csv good.e good.cycles.csv)
signorini_add_driver_test(mesh_too_many_cells_per_rank EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Refinement Level=18" ${decks}/good.xml
  REGEX "Mesh/Cells X = 4, Cells Y = 4, Refinement Level = 18: a mesh of 1[.]1e[+]12 cells on 2 rank[(]s[)]: .* more than the .* that 32-bit local indices allow")
signorini_add_driver_test(mesh_too_large_for_memory EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Cells X=20000" --set "Mesh/Cells Y=20000" ${decks}/good.xml
  REGEX "a mesh of 4e[+]08 cells on 2 rank[(]s[)]: at least 150 GB per rank, more than this machine's")
signorini_add_driver_test(adaptive_uniform_cycles_too_many EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=20" ${decks}/good.xml
  REGEX "Adaptivity/Cycles = 20 with Strategy = uniform: a mesh of .* cells on 2 rank[(]s[)]")

# Expressions that are not a finite number somewhere in the domain (used to reach Belos as "NaN has
# been detected", naming no key); on 2 ranks the point lies in one rank's cells only.
signorini_add_driver_test(bad_initial_velocity_not_a_number EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Initial Velocity=sqrt(x - 0.5)" ${decks}/good.xml
  REGEX "Problem/Initial Velocity: 'sqrt[(]x - 0[.]5[)]' evaluates to nan at [(]")
signorini_add_driver_test(bad_body_force_infinite_on_one_rank EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Body Force=y > 0.6 ? 1/(x - x) : 0" ${decks}/good.xml
  REGEX "Problem/Body Force: .* evaluates to inf at [(]")
# A sublist given a value, and bounds printed with their digits (0.4999999 printed as 0.5).
signorini_add_driver_test(set_sublist_as_value EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity=3" ${decks}/good.xml
  REGEX "--set 'Adaptivity=3': 'Adaptivity' is a sublist: set one of its entries")
signorini_add_driver_test(poisson_ratio_bound_digits EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Poisson's Ratio=0.5" ${decks}/good.xml
  REGEX "'Problem/Poisson's Ratio' = 0[.]5 is not allowed; it must be in [[]0, 0[.]4999999[]]")

# A value just out of range is quoted with every digit it needs (it was rounded to "1", which the
# range [0, 1] allows).
signorini_add_driver_test(out_of_range_value_quoted_exactly EXIT 1
  ARGS --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Refinement Fraction=1.0000000001"
       ${decks}/good.xml
  REGEX "'Adaptivity/Refinement Fraction' = 1[.]0000000001 is not allowed; it must be in [[]0, 1[]]")
# A basename like an adaptive run's cycle files ("x.cycle7") would be retired by a run under "x".
signorini_add_driver_test(basename_like_cycle_files EXIT 1
  ARGS --output-dir {OUT} --set "Output/Basename=x.cycle7" ${decks}/good.xml
  REGEX "Output/Basename 'x[.]cycle7', which ends like the cycle files of a run under the basename 'x'")
signorini_add_driver_test(basename_cycle_without_number EXIT 0
  ARGS --check --output-dir {OUT} --set "Output/Basename=x.cycle" ${decks}/good.xml
  REGEX "is valid")
# --check: a valid deck is set up and described, nothing is written; a bad deck fails as a run would.
signorini_add_driver_test(check_valid_deck EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=bulk" --set "Adaptivity/Cycles=3" ${decks}/good.xml
  REGEX "checking .*good[.]xml on 2 rank[(]s[)]" "good[.]xml is valid; the run would do:"
        "4 steps of k = 0[.]0025 to T = 0[.]01; the initial mesh: 16 cells, 25 unknowns"
        "Algorithm 5[.]1: 3 cycle[(]s[)], strategy bulk 50%"
        "Newmark alpha = 0[.]5, beta = 0[.]5, contact force trapezoidal [(]the paper's[)], contact stabilisation none"
        # c k / h_min = 1 x 0.0025 / 0.25; two cycles after the first refine at most two levels
        "linear solver: CG [+] Jacobi on the initial mesh [(]Preconditioner = auto: c k / h_min = 0[.]01, up to 0[.]04 on meshes 2 levels finer; MueLu above 5[)]")
# The plan names the probes and the implicit contact force.
signorini_add_driver_test(check_names_probes_and_scheme EXIT 0
  ARGS --check --output-dir {OUT} --set "Output/Probes/middle=0.5, 0.5" --set "Output/Probes/edge=1, 0.25"
       --set "Output/Probe Fields=u, v" --set "Time Integration/Contact Force=implicit" --set "Time Integration/Beta=0.25"
       ${decks}/good.xml
  REGEX "probes [(]u, v, points of the undeformed body[)]: (middle at [(]0[.]5, 0[.]5[)], edge at [(]1, 0[.]25[)]|edge at [(]1, 0[.]25[)], middle at [(]0[.]5, 0[.]5[)])"
        "Newmark alpha = 0[.]5, beta = 0[.]25, contact force implicit [(]Deuflhard, Krause, Ertel[)]")
# The plan says where "auto" switches to MueLu (c k / h_min = 0.16 on the deck's mesh at
# k = 0.04, 2.56 four levels finer; the threshold lowered to 1).
signorini_add_driver_test(check_plan_muelu_on_finer_meshes EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=5"
       --set "Time Integration/Time Step=0.04" --set "Time Integration/Final Time=0.08"
       --set "Linear Solver/Auto MueLu Courant Number=1" ${decks}/good.xml
  REGEX "linear solver: CG [+] Jacobi on the initial mesh [(]Preconditioner = auto: c k / h_min = 0[.]16, up to 2[.]56 on meshes 4 levels finer; MueLu above 1, so on the finer meshes[)]")
# --check writes nothing, not even the output directory it checks (it creates and removes it).
signorini_add_driver_test(check_creates_no_directory EXIT 0
  ARGS --check --output-dir {OUT}/new/deeper ${decks}/good.xml
  REGEX "good[.]xml is valid")
signorini_add_driver_test(check_unwritable_output_dir EXIT 1
  ARGS --check --output-dir /dev/null/out ${decks}/good.xml
  REGEX "--output-dir: cannot write to '/dev/null/out'")
# The plan of a uniform run counts the cycles the Maximum Level allows and no coarsening.
signorini_add_driver_test(check_uniform_plan EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=20"
       --set "Adaptivity/Maximum Level=3" --set "Adaptivity/Coarsening Fraction=0.4" ${decks}/good.xml
  REGEX "Algorithm 5[.]1: 20 cycle[(]s[)] [(]4: then every cell is at Maximum Level 3[)], strategy uniform\n")
# The coarse Schur correction's mesh: the finest uniform level <= Mesh/Refinement Level with at
# most Contact/Coarse Correction Cells cells (good.xml: 4 x 4 cells, one p4est tree, so levels
# down to -2). 16 * 4^l cells: level 1 (64 cells, 9 x 9 nodes) is the last within 100; 4 cells
# (level -1, 3 x 3 nodes) the last within 10; the tree itself (1 cell) below 4.
signorini_add_driver_test(check_coarse_correction_level EXIT 0
  ARGS --check --output-dir {OUT} --set "Contact/Schur Preconditioner=strip + coarse" --set "Mesh/Refinement Level=3"
       --set "Contact/Coarse Correction Cells=100" ${decks}/good.xml
  REGEX "coarse correction: 64 cells [(]Refinement Level 1[)], 81 unknowns\n")
signorini_add_driver_test(check_coarse_correction_below_level_0 EXIT 0
  ARGS --check --output-dir {OUT} --set "Contact/Schur Preconditioner=strip + coarse" --set "Mesh/Refinement Level=1"
       --set "Contact/Coarse Correction Cells=10" ${decks}/good.xml
  REGEX "coarse correction: 4 cells [(]Refinement Level -1[)], 9 unknowns\n")
# A run whose contact QP uses the correction on the tree itself, through contact (some step has
# active segments: the membrane at x = 1 moves at speed 1 toward an obstacle 0.05-0.2 away).
signorini_add_driver_test(coarse_correction_on_the_tree EXIT 0
  ARGS --output-dir {OUT} --set "Contact/Schur Preconditioner=strip + coarse" --set "Mesh/Refinement Level=1"
       --set "Contact/Coarse Correction Cells=3" --set "Time Integration/Final Time=0.25"
       --set "Output/Progress Interval=1" ${decks}/good.xml
  REGEX "step [0-9]+/100 .* active = [1-9]" "good[.]xml done: 100 steps"
  FILES good.steps.csv good.e)
# An Exodus mesh has one tree per cell: its 16 trees are the coarsest mesh, more than the 10 asked for.
signorini_add_driver_test(check_coarse_correction_more_than_asked EXIT 0
  ARGS --check --output-dir {OUT} --set "Contact/Schur Preconditioner=strip + coarse" --set "Mesh/Refinement Level=2"
       --set "Contact/Coarse Correction Cells=10" ${decks}/good-exodus.xml
  REGEX "coarse correction: 16 cells [(]Refinement Level 0[)], 25 unknowns, the coarse mesh's trees: more than Contact/Coarse Correction Cells = 10\n")
signorini_add_driver_test(coarse_correction_cells_without_effect EXIT 0
  ARGS --check --output-dir {OUT} --set "Contact/Schur Preconditioner=lumped" --set "Contact/Coarse Correction Cells=100"
       --set "Contact/Strip Width=3" ${decks}/good.xml
  REGEX "warning: .*Contact/Schur Preconditioner = lumped; without effect: Contact/Coarse Correction Cells, Contact/Strip Width\n")
# good.xml: 4 steps on 5 x 5 nodes, so cycle 0 alone has 100 total unknowns; the plan says that a
# limit of 100 ends the run after it (and 101 does not).
signorini_add_driver_test(check_plan_stops_after_cycle_0 EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=3"
       --set "Adaptivity/Maximum Total Unknowns=100" ${decks}/good.xml
  REGEX "stop at 100 total unknowns [(]cycle 0 alone has 100: the run stops after it[)]\n")
signorini_add_driver_test(check_plan_goes_past_cycle_0 EXIT 0
  ARGS --check --output-dir {OUT} --set "Adaptivity/Strategy=uniform" --set "Adaptivity/Cycles=3"
       --set "Adaptivity/Maximum Total Unknowns=101" ${decks}/good.xml
  REGEX "stop at 101 total unknowns\n")
signorini_add_driver_test(check_bad_deck EXIT 1
  ARGS --check --output-dir {OUT} ${decks}/good.xml ${decks}/penetrating.xml
  REGEX "good[.]xml is valid" "Problem/Initial Displacement penetrates the obstacle" "1 of 2 deck[(]s[)] failed")

# Reproducible arithmetic covers scalar problems with the Jacobi preconditioner; anything else is
# refused before a file is written.
signorini_add_driver_test(reproducible_arithmetic_needs_jacobi EXIT 1
  ARGS --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" --set "Linear Solver/Preconditioner=MueLu"
       ${decks}/good.xml
  REGEX "Linear Solver/Preconditioner: reproducible arithmetic needs \"Jacobi\" [(]or \"auto\"[)], not \"MueLu\"")
signorini_add_driver_test(reproducible_arithmetic_needs_cg EXIT 1
  ARGS --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" --set "Linear Solver/Method=GMRES"
       ${decks}/good.xml
  REGEX "Linear Solver/Method: reproducible arithmetic solves with its own Jacobi CG and needs \"CG\", not \"GMRES\"")
signorini_add_driver_test(unknown_krylov_method EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Method=CGG" ${decks}/good.xml
  REGEX "Linear Solver/Method: \"CGG\" is not one of the Krylov methods for these symmetric positive definite systems: CG, PSEUDOBLOCK CG, ")
# Belos knows BICGSTAB, but it needs a right preconditioner: refused before the run, not at the first solve.
signorini_add_driver_test(krylov_method_needing_a_right_preconditioner EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Method=BICGSTAB" ${decks}/good.xml
  REGEX "Linear Solver/Method: \"BICGSTAB\" is not one of the Krylov methods")
# Contact Direction along the outward normal or tangential (the bar's foundation is its bottom: +y):
# the obstacle would be inside the body or along its boundary; it ran without ever touching.
signorini_add_driver_test(contact_direction_outward EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Contact Direction=-y" ${PROJECT_SOURCE_DIR}/inputs/bar.xml
  REGEX "Problem/Contact Direction: on no contact edge does it point into the body")
signorini_add_driver_test(contact_direction_tangential EXIT 1
  ARGS --check --output-dir {OUT} --set "Problem/Contact Direction=+x" ${PROJECT_SOURCE_DIR}/inputs/bar.xml
  REGEX "Problem/Contact Direction: on no contact edge does it point into the body")
# A Neumann segment over Dirichlet edges under another name (the same name is refused with the deck).
signorini_add_driver_test(neumann_edges_on_dirichlet_edges EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/n=left, y > 0.5" --set "Problem/Neumann Segments=n"
       --set "Problem/Neumann Data=1" ${decks}/good.xml
  REGEX "Problem: a boundary edge belongs to both a Neumann segment and a Dirichlet segment")
# Initial data against the boundary conditions, warned about (not errors: the run is defined):
# a displacement not 0 where the body is clamped, an obstacle above the initial displacement at
# points of the contact boundary while the segment means keep the discrete constraint.
signorini_add_driver_test(initial_displacement_on_dirichlet_segments EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Initial Displacement=0.3" ${decks}/good.xml
  REGEX "warning: .*Problem/Initial Displacement is not 0 on the Dirichlet segments [(]up to 0.3[)]")
signorini_add_driver_test(obstacle_above_initial_displacement_at_points EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=y < 0.1 ? 0.05 : -1" ${decks}/good.xml
  REGEX "warning: .*Problem/Obstacle lies above Problem/Initial Displacement at points of the contact boundary [(]by up to 0.05 at [(]1, 0[)][)]")
# Along some contact edges and into the body on others, d . u >= g is valid (the bar's right face
# added to its foundation, with a floor that descends along it): no error, no warning.
signorini_add_driver_test(contact_direction_along_some_edges EXIT 0
  ARGS --check --output-dir {OUT} --set "Mesh/Boundary Segments/r=right" --set "Problem/Contact Segments=foundation, r"
       --set "Problem/Obstacle=-0.005 - y" ${PROJECT_SOURCE_DIR}/inputs/bar.xml
  REGEX "bar[.]xml is valid")
# A time step so small that beta k^2 leaves the doubles the estimator needs: a user error naming
# the key (it was an internal assertion in the marking).
signorini_add_driver_test(estimate_not_finite EXIT 1
  ARGS --output-dir {OUT} --set "Time Integration/Time Step=1e-100" --set "Time Integration/Final Time=1e-100"
       --set "Adaptivity/Strategy=fixed fraction" --set "Adaptivity/Cycles=2" ${decks}/good.xml
  REGEX "the estimator's indicators are not finite numbers: Time Integration/Time Step = 1e-100 gives beta k.2 = ")
# Checks of the MueLu sublist on a mesh where the deck sets MueLu up.
set(muelu_check --check --output-dir {OUT} --set "Mesh/Refinement Level=4" --set "Linear Solver/Preconditioner=MueLu")
# MueLu keys that signorini sets itself: on 2 ranks "number of equations = 3" failed MueLu's set-up
# on one rank only and left the other waiting inside MueLu (a hang); refused before the run.
signorini_add_driver_test(muelu_key_set_by_signorini EXIT 1
  ARGS ${muelu_check}
       --set "Linear Solver/MueLu/number of equations=3" ${decks}/good.xml
  REGEX "Linear Solver/MueLu/number of equations: set by signorini from the unknowns per node of Problem/Type")
# MueLu takes a level count below 1 and then crashed in its set-up (a segmentation fault): refused.
signorini_add_driver_test(muelu_max_levels_below_one EXIT 1
  ARGS ${muelu_check}
       --set "Linear Solver/MueLu/max levels=0" ${decks}/good.xml
  REGEX "Linear Solver/MueLu/max levels: 0 is below 1")
signorini_add_driver_test(muelu_value_not_finite EXIT 1
  ARGS ${muelu_check}
       --set "Linear Solver/MueLu/aggregation: drop tol=nan" ${decks}/good.xml
  REGEX "Linear Solver/MueLu/aggregation: drop tol: nan is not a finite number")
# --set cannot know a MueLu key's type: "0" for a double, "1e3" for an int and "yes" for a bool take
# the type of MueLu's master list (MueLu refused them: "the correct type is double").
signorini_add_driver_test(muelu_values_take_muelus_types EXIT 0
  ARGS --output-dir {OUT} --set "Mesh/Refinement Level=3" --set "Linear Solver/Preconditioner=MueLu"
       --set "Linear Solver/MueLu/aggregation: drop tol=0" --set "Linear Solver/MueLu/coarse: max size=1e3"
       --set "Linear Solver/MueLu/problem: symmetric=yes" --set "Output/Write Exodus=false" ${decks}/good.xml
  REGEX "wrote .*good[.]steps[.]csv"
  FILES good.steps.csv)
# The log names an Exodus series' further files in one line (first, last, count), the others one by one.
signorini_add_driver_test(exodus_series_in_one_line EXIT 0 NP 1
  ARGS --output-dir {OUT} --set "Adaptivity/Cycles=2" --set "Time Integration/Final Time=0.2"
       ${PROJECT_SOURCE_DIR}/inputs/membrane.xml
  REGEX "wrote [^ ]*/membrane[.]e\n"
        "wrote [^ ]*/membrane[.]e-s[.]0001 [.][.][.] [^ ]*/membrane[.]e-s[.]0009 [(]9 files of the series of [^ ]*/membrane[.]e[)]"
  ABSENT "wrote [^ ]*/membrane[.]e-s[.]0002"
  FILES membrane.cycle0.steps.csv membrane.steps.csv membrane.cycles.csv membrane.e membrane.e-s.0001 membrane.e-s.0002
        membrane.e-s.0003 membrane.e-s.0004 membrane.e-s.0005 membrane.e-s.0006 membrane.e-s.0007 membrane.e-s.0008
        membrane.e-s.0009)
# Output names the Exodus library would change or that break listings (it dropped the leading blanks
# of "   /good.e": the file went to the root folder while the tables went to "   /").
signorini_add_driver_test(output_directory_with_leading_blanks EXIT 1
  ARGS --set "Output/Directory=   " ${decks}/good.xml
  REGEX "Output/Directory '   ': begins with a blank, which the Exodus library would drop")
signorini_add_driver_test(output_dir_option_with_leading_blank EXIT 1
  ARGS --output-dir " {OUT}" ${decks}/good.xml
  REGEX "--output-dir ' .*out': begins with a blank")
signorini_add_driver_test(basename_with_control_character EXIT 1
  ARGS --output-dir {OUT} "--set=Output/Basename=a	b" ${decks}/good.xml
  REGEX "Output/Basename: contains a control character [(]byte 9[)]")
# Exact solution data whose error norms overflow: a user error, not inf in every row with exit 0.
signorini_add_driver_test(exact_solution_norms_not_finite EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Exact Solution=1e300*x" ${decks}/good.xml
  REGEX "Problem/Exact Solution: the error norms of step 0 [(]t = 0[)] are not finite numbers")
# Data so large that the estimate overflows: named as the data, not as the time step.
signorini_add_driver_test(estimate_not_finite_from_the_data EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Initial Velocity=1e200*x" --set "Adaptivity/Strategy=fixed fraction"
       --set "Parallel/Reproducible Arithmetic=true" --set "Adaptivity/Cycles=2" ${decks}/good.xml
  REGEX "the estimator's indicators are not finite numbers: the squares of its residuals leave the range of doubles [(]the solution reaches .*[)]; are the problem's data")
# Cells too small for their coordinates: far from the origin shifting helps, a degenerate rectangle
# (its sides 1 and 1e-300) needs other sides or cells, wherever it lies.
signorini_add_driver_test(rectangle_far_from_the_origin EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/X0=1e12" --set "Mesh/X1=1000000000001" ${decks}/good.xml
  REGEX "cells of .* are below 1e-10 of them [(]doubles resolve 1e-16; shift the rectangle toward the origin[)]")
signorini_add_driver_test(degenerate_rectangle EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Y1=1e-300" ${decks}/good.xml
  REGEX "the rectangle's sides, 1 and 1e-300, or its cells along them differ too much")
# A contact boundary of so many segments that the QP's dense matrices cannot fit: a user error before
# they are allocated (a --check with 50,000 segments grew to 24 GB and was killed). The budget makes
# the test independent of the machine's memory; the control fits the same mesh with a larger one.
signorini_add_driver_test(contact_qp_memory EXIT 1
  ARGS --check --output-dir {OUT} --set "Mesh/Cells Y=2000" --set "Parallel/Memory Per Rank=0.1" ${decks}/good.xml
  REGEX "Problem/Contact Segments: 1000 contact multiplier segments and a Schur strip of at least [0-9]+ nodes need at least [0-9.]+ GB for the contact QP's dense matrices, more than the 0.1 GB per rank of Parallel/Memory Per Rank")
signorini_add_driver_test(contact_qp_memory_control EXIT 0
  ARGS --check --output-dir {OUT} --set "Mesh/Cells Y=2000" --set "Parallel/Memory Per Rank=4" ${decks}/good.xml
  REGEX "good[.]xml is valid")
# Under reproducible arithmetic a body force whose squares overflow made the Jacobi CG run out of
# iterations, and the message blamed Linear Solver/Maximum Iterations.
signorini_add_driver_test(reproducible_solve_with_data_beyond_doubles EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Body Force=1e160" --set "Parallel/Reproducible Arithmetic=true" ${decks}/good.xml
  REGEX "linear solver CG [+] Jacobi [(]reproducible[)] for the step matrix .* stopped: the squares of the right-hand side or of the iterate leave the range of doubles")
signorini_add_driver_test(reproducible_solve_out_of_iterations EXIT 1  # the control: finite data
  ARGS --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" ${decks}/solver-failure.xml
  REGEX "linear solver CG [+] Jacobi [(]reproducible[)] for the step matrix .* did not reach the relative tolerance 1e-10 in 3 iterations [(]Linear Solver/Maximum Iterations[)]")
# Segment names the Problem lists cannot name (they split at commas and drop blanks).
signorini_add_driver_test(segment_name_with_a_comma EXIT 1
  ARGS --check --output-dir {OUT} "--set=Mesh/Boundary Segments/a,b=top" ${decks}/good.xml
  REGEX "Mesh/Boundary Segments/a,b: a segment name with a comma or with blanks at either end")
# A string value that is not one of the choices is shown quoted (its blanks show).
signorini_add_driver_test(choice_value_quoted EXIT 1
  ARGS --check --output-dir {OUT} "--set=Problem/Type= scalar wave" ${decks}/good.xml
  REGEX "'Problem/Type' = \" scalar wave\" is not allowed; it must be one of")
# The coarse correction is factored on every rank: bounded (2^31 - 1 cells ran out of memory after 93 s).
signorini_add_driver_test(coarse_correction_cells_bounded EXIT 1
  ARGS --check --output-dir {OUT} --set "Contact/Coarse Correction Cells=2147483647" ${decks}/good.xml
  REGEX "'Contact/Coarse Correction Cells' = 2147483647 is not allowed; it must be in [[]1, 65536[]]")
# A Belos setting that Belos refuses only when it solves (GCRODR's recycled blocks against its
# subspace): a user error naming the sublist, not Belos' text as an unexpected error.
signorini_add_driver_test(belos_setting_refused_at_the_solve EXIT 1
  ARGS --output-dir {OUT} --set "Linear Solver/Method=GCRODR" --set "Mesh/Refinement Level=2"
       --set "Linear Solver/Belos/Num Blocks=2" ${decks}/good.xml
  REGEX "Linear Solver/Belos: Belos' \"GCRODR\" cannot solve with these parameters: .*recycled blocks")
# DESIGN 1.6 names RCG, but Trilinos 13.2's Belos factory does not register it for Tpetra: refused
# before the run with the reason, not as an unexpected error at the first solve.
signorini_add_driver_test(krylov_method_not_registered EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Method=rcg" ${decks}/good.xml
  REGEX "RCG [(]recycling CG[)] is not registered in this Trilinos's Belos solver factory for Tpetra")
signorini_add_driver_test(reproducible_arithmetic_method_in_any_case EXIT 0
  ARGS --check --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" --set "Linear Solver/Method=cg"
       ${decks}/good.xml
  REGEX "good[.]xml is valid")
signorini_add_driver_test(reproducible_arithmetic_ignores_belos_sublist EXIT 0
  ARGS --check --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" --set "Linear Solver/Belos/Verbosity=1"
       ${decks}/good.xml
  REGEX "warning: .*good[.]xml: reproducible arithmetic solves with its own Jacobi CG; without effect: Linear Solver/Belos\n"
        "good[.]xml is valid")
# Data beyond the range of doubles: Belos meets a NaN residual, a solver failure about the data.
signorini_add_driver_test(body_force_beyond_doubles EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Body Force=1e200" ${decks}/good.xml
  REGEX "solver failure: linear solver CG [+] Jacobi for the mass matrix M [(]initial data, contact stabilisation, the implicit contact force.s acceleration; always with Jacobi[)] stopped: a residual is not a number")
# Density, stiffness and Young's modulus are held within 1e-100..1e100 (the solvers' squared norms
# leave the doubles beyond; a density and stiffness of 1e-160 lost the initial velocity silently).
signorini_add_driver_test(density_out_of_range EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Density=1e-160" --set "Problem/Stiffness=1e-160" ${decks}/good.xml
  REGEX "'Problem/Density' = 1e-160 is not allowed; it must be in [[]1e-100, 1e[+]100[]]")

# The contact problem's own inconsistencies.
# An obstacle given as two expressions (a vector by mistake) used to evaluate to the last one.
signorini_add_driver_test(obstacle_two_expressions EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Obstacle=-0.05, 0" ${decks}/good.xml
  REGEX "Problem/Obstacle: expected 1 comma-separated expression, got 2 in '-0[.]05, 0'")
# A contact segment inside a Dirichlet segment of another name used to fail an internal assertion.
signorini_add_driver_test(contact_inside_dirichlet_other_name EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Boundary Segments/lefthalf=left, y > 0.5" --set "Problem/Contact Segments=lefthalf"
       --set "Problem/Obstacle=-0.1" ${decks}/good.xml
  REGEX "Problem: a boundary edge belongs to both a contact segment and a Dirichlet segment that fixes the constrained component")
signorini_add_driver_test(contact_and_neumann_same_segment EXIT 1
  ARGS --output-dir {OUT} --set "Problem/Neumann Segments=contact" ${decks}/good.xml
  REGEX "Problem/Contact Segments and Problem/Neumann Segments name the same segment")
signorini_add_driver_test(contact_and_neumann_other_name EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Boundary Segments/r2=right" --set "Problem/Neumann Segments=r2" ${decks}/good.xml
  REGEX "Problem: a boundary edge belongs to both a contact segment and a Neumann segment")
signorini_add_driver_test(contact_segments_without_obstacle EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=" ${decks}/good.xml
  REGEX "warning: .*Problem/Contact Segments without Problem/Obstacle: no contact\n")
# Keys that the chosen solver does not read: the Courant number of "auto" under another
# preconditioner, the cache of the cached-columns Newton step under CG.
signorini_add_driver_test(courant_number_without_auto EXIT 0
  ARGS --check --output-dir {OUT} --set "Linear Solver/Preconditioner=Jacobi"
       --set "Linear Solver/Auto MueLu Courant Number=2" ${decks}/good.xml
  REGEX "warning: .*Linear Solver/Preconditioner = Jacobi; without effect: Linear Solver/Auto MueLu Courant Number\n")
signorini_add_driver_test(cached_columns_without_cache EXIT 0
  ARGS --check --output-dir {OUT} --set "Contact/Newton Step Solver=CG" --set "Contact/Cached Columns=5" ${decks}/good.xml
  REGEX "warning: .*Contact/Newton Step Solver = CG; without effect: Contact/Cached Columns\n")
signorini_add_driver_test(contact_keys_without_obstacle EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Obstacle=" --set "Problem/Contact Segments="
       --set "Contact/Strip Width=3" --set "Contact/Multiplier Segments=H = h" ${decks}/good.xml
  REGEX "warning: .*no Problem/Obstacle; without effect: Contact/(Multiplier Segments, Contact/Strip Width|Strip Width, Contact/Multiplier Segments)\n")
# The KKT tolerance is absolute: the paper's membrane scaled down by 1e10 is warned about before it
# runs. Its largest initial mean gap is on the segments [0, 0.5] and [0.5, 1] of x = 1 (4 x 4 cells,
# H = 2h): (1.05 - 2/pi) 1e-10 = 4.13e-11, against a tolerance of 1e-9 sqrt(2) = 1.41e-9.
signorini_add_driver_test(contact_gaps_near_tolerance EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Initial Velocity=-1e-10*sin(pi*x/2)"
       --set "Problem/Obstacle=1e-10*(sin(pi*y) - 1.05)" ${decks}/good.xml
  REGEX "warning: .*the largest initial gap, 4[.]13e-11, is within 1000 times the contact tolerance 1[.]41e-09 .*lower Contact/KKT Tolerance\n")
# A named contact segment along which the contact direction runs (-x on the top side) is most
# likely named by mistake: a warning naming it; the right side alone draws none (the control).
signorini_add_driver_test(contact_segment_along_the_direction EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Type=plane strain elasticity" --set "Problem/Initial Velocity=0, 0"
       --set "Problem/Contact Direction=-x" --set "Problem/Obstacle=-0.1" --set "Mesh/Boundary Segments/lid=top"
       --set "Problem/Contact Segments=contact, lid" ${decks}/good.xml
  REGEX "warning: .*Problem/Contact Segments: on no edge of 'lid' does Problem/Contact Direction point into the body"
  ABSENT "edge of 'contact'")
signorini_add_driver_test(contact_segment_against_the_direction EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Type=plane strain elasticity" --set "Problem/Initial Velocity=0, 0"
       --set "Problem/Contact Direction=-x" --set "Problem/Obstacle=-0.1" ${decks}/good.xml
  REGEX "good[.]xml is valid"
  ABSENT "Problem/Contact Segments: on no edge")
# A body that starts on the obstacle (a free body whose u0, a field of the space, is the obstacle:
# mean gaps of 1e-16) draws no such warning: no tolerance could resolve them (a user review found
# it, with the advice to lower the tolerance).
signorini_add_driver_test(contact_starts_on_the_obstacle EXIT 0
  ARGS --check --output-dir {OUT} --set "Problem/Dirichlet Segments=" --set "Problem/Initial Displacement=0.1*y - 0.5"
       --set "Problem/Obstacle=0.1*y - 0.5" ${decks}/good.xml
  REGEX "good[.]xml is valid"
  ABSENT "largest initial gap")
# A QP that fails names the step, the iteration history and both of its tests (the KKT conditions and
# the gap on the active set).
signorini_add_driver_test(contact_qp_failure_history EXIT 1
  ARGS --output-dir {OUT} --set "Mesh/Refinement Level=2" --set "Problem/Obstacle=0.1*sin(7*pi*y)-0.15"
       --set "Problem/Initial Velocity=-3*sin(pi*x/2)" --set "Time Integration/Final Time=0.3"
       --set "Contact/Maximum Active Set Iterations=1" --set "Contact/Newton Step Solver=CG" ${decks}/good.xml
  REGEX "solver failure: step [0-9]+ [(]t = [^)]*[)]: contact QP: the active set method did not satisfy the KKT conditions within Contact/Maximum Active Set Iterations = 1"
        "iteration 1: [0-9]+ active [(][0-9]+ changed[)], [0-9]+ CG iterations, largest KKT violation [^ ]+ [(]tolerance [^)]+[)], largest gap on the active set [^ ]+ [(]tolerance [^)]+[)]\n")
# H = h on a contact boundary (3 edges, the top) whose both ends are Dirichlet nodes: 3 segments on
# 2 free nodes, Q singular. The multipliers diverged while the updated gaps claimed contact (energy
# 7e33, exit 0); now the QP checks the gaps of u and fails, naming the step. H = 2h is the control.
set(singular_contact --set "Mesh/Cells X=3" --set "Mesh/Cells Y=8" --set "Mesh/Boundary Segments/top=top"
    --set "Problem/Dirichlet Segments=clamped, contact" --set "Problem/Contact Segments=top" --set "Problem/Initial Velocity=0"
    --set "Problem/Obstacle=5*t-0.01" --set "Time Integration/Time Step=0.01" --set "Time Integration/Final Time=0.2")
signorini_add_driver_test(contact_h_singular EXIT 1
  ARGS --output-dir {OUT} ${singular_contact} --set "Contact/Multiplier Segments=H = h" ${decks}/good.xml
  REGEX "solver failure: step [0-9]+ [(]t = [^)]*[)]: contact QP: the multipliers diverged .*Q_AA is singular.*use H = 2h")
signorini_add_driver_test(contact_2h_control EXIT 0
  ARGS --output-dir {OUT} ${singular_contact} --set "Contact/Multiplier Segments=H = 2h" ${decks}/good.xml
  REGEX "good[.]xml done: 20 steps"
  FILES good.steps.csv good.e)
signorini_add_driver_test(muelu_sublist_unknown_key EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Preconditioner=MueLu" --set "Linear Solver/MueLu/bogus key=1"
       ${decks}/good.xml
  REGEX "Linear Solver/MueLu: 'bogus key' is not a MueLu parameter")
signorini_add_driver_test(muelu_sublist_bad_value EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Preconditioner=MueLu" --set "Linear Solver/MueLu/smoother: type=FOO"
       ${decks}/good.xml
  REGEX "Linear Solver/MueLu: MueLu cannot be set up with these parameters: Could not construct any smoother")
signorini_add_driver_test(belos_sublist_key_set_by_signorini EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Belos/Maximum Iterations=1" ${decks}/good.xml
  REGEX "Linear Solver/Belos/Maximum Iterations: set by signorini from Linear Solver/Maximum Iterations; set that instead")
signorini_add_driver_test(muelu_sublist_without_muelu EXIT 0
  ARGS --check --output-dir {OUT} --set "Linear Solver/Preconditioner=Jacobi" --set "Linear Solver/MueLu/verbosity=high"
       ${decks}/good.xml
  REGEX "warning: .*good[.]xml: Linear Solver/Preconditioner = Jacobi; without effect: Linear Solver/MueLu\n"
        "good[.]xml is valid")
signorini_add_driver_test(belos_sublist_unknown_key EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Belos/Bogus Key=1" ${decks}/good.xml
  REGEX "Linear Solver/Belos: 'Bogus Key' is not a parameter of Belos' \"CG\"\n")
signorini_add_driver_test(belos_sublist_misspelt_key EXIT 1
  ARGS --check --output-dir {OUT} --set "Linear Solver/Belos/Output Frequncy=5" ${decks}/good.xml
  REGEX "Linear Solver/Belos: 'Output Frequncy' is not a parameter of Belos' \"CG\" [(]did you mean 'Output Frequency'[?][)]")
signorini_add_driver_test(reproducible_arithmetic_scalar_only EXIT 1
  ARGS --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" --set "Problem/Type=plane strain elasticity"
       ${decks}/good.xml
  REGEX "Parallel/Reproducible Arithmetic: available for Problem/Type = \"scalar wave\" only")
signorini_add_driver_test(check_reproducible_deck EXIT 0
  ARGS --check --output-dir {OUT} --set "Parallel/Reproducible Arithmetic=true" ${decks}/good.xml
  REGEX "good[.]xml is valid; the run would do:" "reproducible arithmetic: the same bits on any number of ranks")

# Ctrl-C and SIGTERM end a run cleanly (no files, exit status 128 + signal); a rerun removes the
# '.part' files of a run that was killed outright.
add_test(NAME driver_interrupted_run
  COMMAND bash ${SIGNORINI_DRIVER_TEST_DIR}/interrupt.sh $<TARGET_FILE:signorini> ${SIGNORINI_MPIEXEC}
          ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/driver/interrupted_run)
set_tests_properties(driver_interrupted_run PROPERTIES TIMEOUT 120 LABELS driver PROCESSORS 2)
# Cases that need a shell: a deck on stdin under mpirun, one output base reached through a link.
add_test(NAME driver_shell_cases
  COMMAND bash ${SIGNORINI_DRIVER_TEST_DIR}/shell_cases.sh $<TARGET_FILE:signorini> ${SIGNORINI_MPIEXEC}
          ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/driver/shell_cases)
set_tests_properties(driver_shell_cases PROPERTIES TIMEOUT 120 LABELS driver PROCESSORS 2)
