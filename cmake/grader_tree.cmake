# Assembles the grader's prepared tree (layout: cmake/grader.cmake) from a reference build.
#   cmake -DMANIFEST=BUILD/grader-manifest.cmake -P cmake/grader_tree.cmake
# The tree is made afresh each time: nothing stale, and nothing in it but what is listed here.
cmake_minimum_required(VERSION 3.18)
include(${MANIFEST})

foreach(_d include lib data rules tests)
  file(REMOVE_RECURSE ${TREE}/${_d})
  file(MAKE_DIRECTORY ${TREE}/${_d})
endforeach()

# Headers: the framework's and the lessons' interface headers (no .cpp: plumbing is compiled below).
file(GLOB _h ${SOURCE}/framework/*.h)
file(COPY ${_h} DESTINATION ${TREE}/include/framework)
foreach(L ${LESSONS})
  file(GLOB _h ${SOURCE}/lessons/${L}/*.h)
  if(_h)
    file(COPY ${_h} DESTINATION ${TREE}/include/lessons/${L})
  endif()
endforeach()

# Compiled code.
file(COPY_FILE ${FRAMEWORK} ${TREE}/lib/framework.a)
file(COPY_FILE ${TEST_SUPPORT} ${TREE}/lib/test_support.a)
# objects(LIST DEST): copy each object as DEST/<its source's file name>.o
function(copy_objects LIST DEST)
  foreach(_o ${LIST})
    get_filename_component(_n ${_o} NAME)   # name.cpp.o
    string(REGEX REPLACE "\\.cpp\\.o$" ".o" _n ${_n})
    if(EXISTS ${DEST}/${_n})
      message(FATAL_ERROR "grader tree: two objects named ${_n} in ${DEST}")
    endif()
    file(COPY_FILE ${_o} ${DEST}/${_n})
  endforeach()
endfunction()

# main() of the tests, with the harness's side of the grader's result channel.
file(MAKE_DIRECTORY ${TREE}/lib/main)
copy_objects("${TEST_MAIN}" ${TREE}/lib/main)

# Data the tests read at run time (tests/support/lesson_files.h: PATHSPACE_TEST_SOURCE_DIR).
file(COPY ${SOURCE}/scenes DESTINATION ${TREE}/data)

# Shared libraries from outside /usr (an OpenMP runtime unpacked into a build folder, as
# scripts/portability.sh does for clang 19): the sandbox shows a step /usr and the tree only, so
# such a library is copied into lib/runtime/ (with the names that link to it in its folder, the
# name the loader asks for among them), linked from there and found there at run time (rpath).
set(_runtime_libs)
foreach(_l ${LIBS})
  if(IS_ABSOLUTE "${_l}" AND EXISTS "${_l}" AND NOT _l MATCHES "^/usr/" AND _l MATCHES "[.]so([.][0-9]+)*$")
    file(MAKE_DIRECTORY ${TREE}/lib/runtime)
    file(REAL_PATH ${_l} _real)
    get_filename_component(_dir ${_real} DIRECTORY)
    get_filename_component(_name ${_real} NAME)
    file(COPY_FILE ${_real} ${TREE}/lib/runtime/${_name})
    file(GLOB _aliases ${_dir}/*.so*)
    foreach(_a ${_aliases})
      get_filename_component(_an ${_a} NAME)
      if(IS_SYMLINK ${_a} AND NOT _an STREQUAL _name)
        file(REAL_PATH ${_a} _ar)
        if(_ar STREQUAL _real)
          file(CREATE_LINK ${_name} ${TREE}/lib/runtime/${_an} SYMBOLIC)
        endif()
      endif()
    endforeach()
    get_filename_component(_ln ${_l} NAME)
    list(APPEND _runtime_libs ${TREE}/lib/runtime/${_ln})
  else()
    list(APPEND _runtime_libs ${_l})
  endif()
endforeach()
set(LIBS "${_runtime_libs}")
if(IS_DIRECTORY ${TREE}/lib/runtime)
  string(APPEND LDFLAGS " -Wl,-rpath,${TREE}/lib/runtime")
endif()

foreach(L ${LESSONS})
  string(SUBSTRING ${L} 0 2 NN)
  if(NOT DEFINED TESTS_${NN})
    continue()
  endif()
  file(MAKE_DIRECTORY ${TREE}/lib/${NN}/reference ${TREE}/lib/${NN}/plumbing ${TREE}/lib/${NN}/tests)
  copy_objects("${REFERENCE_${NN}}" ${TREE}/lib/${NN}/reference)
  copy_objects("${PLUMBING_${NN}}" ${TREE}/lib/${NN}/plumbing)
  copy_objects("${TESTS_${NN}}" ${TREE}/lib/${NN}/tests)
  if(IS_DIRECTORY ${SOURCE}/tests/${L}/data)
    file(COPY ${SOURCE}/tests/${L}/data DESTINATION ${TREE}/data/tests/${L})
  endif()

  # rules/NN.mk: this lesson's compiler and flags, as the reference build compiled it; the
  # headers from the tree instead of the source tree.
  set(_flags "${CXXFLAGS_${NN}}")
  foreach(_o ${OPTIONS_${NN}})
    string(REGEX REPLACE "^SHELL:" "" _o "${_o}")
    string(APPEND _flags " ${_o}")
  endforeach()
  foreach(_d ${DEFINITIONS_${NN}})
    if(_d MATCHES "[ \"'$\\\\]")
      message(FATAL_ERROR "grader tree: lesson ${NN}: definition '${_d}' needs quoting; rules/${NN}.mk cannot hold it")
    endif()
    string(APPEND _flags " -D${_d}")
  endforeach()
  set(_includes "-I${TREE}/include/framework -I${TREE}/include/lessons")
  foreach(_d ${INCLUDES_${NN}})
    if(NOT _d MATCHES "^${SOURCE}/" AND NOT _d IN_LIST IMPLICIT_INCLUDES)
      string(APPEND _includes " -isystem ${_d}")  # a dependency outside the system's folders (e.g. Homebrew)
    endif()
  endforeach()
  # The compiler by its real path, unless that loses the C++ name: clang++ is a link to clang,
  # which, called by that name, links as a C compiler (without the C++ library).
  file(REAL_PATH ${CXX} _cxx)
  get_filename_component(_name ${CXX} NAME)
  get_filename_component(_real ${_cxx} NAME)
  if(_name MATCHES "[+][+]" AND NOT _real MATCHES "[+][+]")
    set(_cxx ${CXX})
  endif()
  string(REPLACE ";" " " _libs "${LIBS}")
  file(WRITE ${TREE}/rules/${NN}.mk
    "# Lesson ${L}: compiler and flags of the reference build (cmake/grader_tree.cmake).\n"
    "CXX := ${_cxx}\nCXXFLAGS := ${_flags}\nINCLUDES := ${_includes}\n"
    "LDFLAGS := ${LDFLAGS}\nLIBS := ${_libs}\n")

  # tests/NN-name.txt: the graded tests, as the reference's test program lists them; each must be
  # selected alone by its name (doctest's --test-case takes wildcards and is case-insensitive).
  execute_process(COMMAND ${TEST_PROGRAM_${NN}} --list-test-cases OUTPUT_VARIABLE _out RESULT_VARIABLE _rc)
  string(REGEX MATCH "=+\n(.*)\n=+\n" _list "${_out}")
  if(NOT _rc EQUAL 0 OR NOT CMAKE_MATCH_1)
    message(FATAL_ERROR "grader tree: ${TEST_PROGRAM_${NN}} --list-test-cases failed:\n${_out}")
  endif()
  file(WRITE ${TREE}/tests/${L}.txt "${CMAKE_MATCH_1}\n")
endforeach()
file(COPY_FILE ${SOURCE}/tools/grade/lesson.mk ${TREE}/rules/lesson.mk)
# Where the reference was built: the paths compiled into its objects (a test's file name in
# doctest's messages), which the grader replaces by neutral names in its feedback.
file(WRITE ${TREE}/reference-paths.txt "${SOURCE}\n${BINARY}\n")
message(STATUS "grader tree: ${TREE}")
