# The imported target signorini_deps::trilinos, after find_package(Trilinos) and find_package(MPI).
# Used by the build (SignoriniDependencies.cmake) and, installed, by signorini-config.cmake.
#
# Kokkos' backend and architecture flags (-fopenmp for OpenMP, --expt-extended-lambda -arch=sm_XX
# for CUDA, -march=...): Trilinos 13.2 (TriBITS) puts them on no target, only into
# Trilinos_CXX_COMPILER_FLAGS, mixed with the flags Trilinos itself was built with (Debian's are
# "-g -O2 -ffile-prefix-map=... -fstack-protector-strong -Wformat ... -D_FORTIFY_SOURCE=2", which
# would override the build type's optimisation). Only the Kokkos ones are kept and added to the
# compile (and link) options of the target; -DSIGNORINI_KOKKOS_CXX_FLAGS="..." replaces them.

# signorini_kokkos_flags(<out> <flags>): the Kokkos-related flags of a compiler command line,
# a flag that takes the next word as its value kept together as "SHELL:<flag> <value>".
function(signorini_kokkos_flags out flags)
  separate_arguments(words UNIX_COMMAND "${flags}")
  set(kept "")
  set(pending "")
  foreach(w IN LISTS words)
    if(pending)
      list(APPEND kept "SHELL:${pending} ${w}")
      set(pending "")
    elseif(w MATCHES "^(-x|-Xcompiler|-Xcudafe|-Xopenmp-target|-Xsycl-target-backend|-arch)$")
      set(pending "${w}")
    elseif(w MATCHES "^-f?openmp|^-[qQ]openmp|^-mp(=.*)?$|^-pthreads?$"                  # OpenMP, threads
           OR w MATCHES "^-m(arch|tune|cpu)=|^-mavx|^-x(AVX|CORE-|MIC-|SSE|HOST$|Host$)|^-tp=" # architecture
           OR w MATCHES "^-Xcompiler=|^-Xcudafe="                                           # nvcc, one word
           OR w MATCHES "^-arch=|^--?cuda-gpu-arch=|^--?(amdgpu-target|offload-arch)="      # GPU architecture
           OR w MATCHES "^--?expt-|^--?extended-lambda$|^-Wext-lambda|^--cuda-path="        # CUDA
           OR w MATCHES "^--?relocatable-device-code|^-rdc=|^-f(no-)?(cuda|gpu)-rdc$"       # CUDA/HIP rdc
           OR w MATCHES "^-Wno-unknown-cuda-version$|^-fsycl")                              # SYCL
      list(APPEND kept "${w}")
    endif()
  endforeach()
  set(${out} "${kept}" PARENT_SCOPE)
endfunction()

if(DEFINED SIGNORINI_KOKKOS_CXX_FLAGS)
  set(SIGNORINI_KOKKOS_FLAGS "")
  if(NOT SIGNORINI_KOKKOS_CXX_FLAGS STREQUAL "")
    set(SIGNORINI_KOKKOS_FLAGS "SHELL:${SIGNORINI_KOKKOS_CXX_FLAGS}")  # as given: order kept, nothing merged
  endif()
else()
  signorini_kokkos_flags(SIGNORINI_KOKKOS_FLAGS "${Trilinos_CXX_COMPILER_FLAGS}")
endif()

if(NOT TARGET signorini_deps::trilinos)
  add_library(signorini_deps::trilinos INTERFACE IMPORTED)
  set_target_properties(signorini_deps::trilinos PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${Trilinos_INCLUDE_DIRS};${Trilinos_TPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${Trilinos_LIBRARIES};${Trilinos_TPL_LIBRARIES};MPI::MPI_CXX")
  if(SIGNORINI_KOKKOS_FLAGS)
    set(_signorini_compile "")
    set(_signorini_link "")
    foreach(f IN LISTS SIGNORINI_KOKKOS_FLAGS)
      list(APPEND _signorini_compile "$<$<COMPILE_LANGUAGE:CXX>:${f}>")
      if(NOT f MATCHES "^SHELL:-x ")  # "-x cuda" would make the linker compile the objects
        list(APPEND _signorini_link "${f}")
      endif()
    endforeach()
    set_target_properties(signorini_deps::trilinos PROPERTIES
      INTERFACE_COMPILE_OPTIONS "${_signorini_compile}" INTERFACE_LINK_OPTIONS "${_signorini_link}")
    unset(_signorini_compile)
    unset(_signorini_link)
  endif()
endif()
