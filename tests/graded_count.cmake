# Every graded test the sources declare is one that CTest runs (CTest test graded-test-count).
# A lesson's test program that did not build (a compiler that rejects one test file, a student's
# piece that does not compile) leaves CTest with no test of that lesson, and `ctest -L lesson-NN`
# then finds nothing and passes. This check counts, per lesson, the TEST_CASEs of tests/NN-name/*.cpp
# and the tests CTest lists with the label lesson-NN; they must be equal. It also fails on any
# test program doctest reports as not built (CTest's "*_NOT_BUILT*" placeholder tests).
#   cmake -DSOURCE=tests -DBUILD=build -DCTEST=ctest -P tests/graded_count.cmake
cmake_minimum_required(VERSION 3.16)
if(NOT SOURCE OR NOT BUILD OR NOT CTEST)
  message(FATAL_ERROR "usage: cmake -DSOURCE=tests -DBUILD=build -DCTEST=ctest -P graded_count.cmake")
endif()

execute_process(COMMAND ${CTEST} -N WORKING_DIRECTORY ${BUILD} OUTPUT_VARIABLE _all RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "ctest -N failed in ${BUILD}:\n${_all}")
endif()
set(_failed "")
string(REGEX MATCHALL "Test +#[0-9]+: [^\n]*_NOT_BUILT[^\n]*" _notBuilt "${_all}")
foreach(_t ${_notBuilt})
  string(REGEX REPLACE "^Test +#[0-9]+: " "" _t "${_t}")
  list(APPEND _failed "${_t}: a test program did not build, its tests are missing")
endforeach()

file(GLOB _dirs LIST_DIRECTORIES true RELATIVE ${SOURCE} ${SOURCE}/[0-9][0-9]-*)
list(SORT _dirs)
set(_total 0)
foreach(_d ${_dirs})
  if(NOT IS_DIRECTORY ${SOURCE}/${_d})
    continue()
  endif()
  string(SUBSTRING ${_d} 0 2 NN)
  file(GLOB _files ${SOURCE}/${_d}/*.cpp)
  set(_declared 0)
  foreach(_f ${_files})
    file(STRINGS ${_f} _cases REGEX "^[ \t]*TEST_CASE[ \t]*\\(")
    list(LENGTH _cases _n)
    math(EXPR _declared "${_declared} + ${_n}")
  endforeach()
  execute_process(COMMAND ${CTEST} -N -L "^lesson-${NN}$" WORKING_DIRECTORY ${BUILD} OUTPUT_VARIABLE _out)
  string(REGEX MATCH "Total Tests: ([0-9]+)" _m "${_out}")
  set(_listed "${CMAKE_MATCH_1}")
  if(NOT "${_listed}" STREQUAL "${_declared}")
    list(APPEND _failed
         "lesson ${NN}: tests/${_d}/*.cpp declare ${_declared} graded tests, CTest lists ${_listed} (label lesson-${NN}): is lesson_${NN}_tests built?")
  endif()
  math(EXPR _total "${_total} + ${_declared}")
endforeach()
if(_failed)
  string(REPLACE ";" "\n  " _f "${_failed}")
  message(FATAL_ERROR "graded tests missing from CTest:\n  ${_f}")
endif()
list(LENGTH _dirs _lessons)
message(STATUS "graded tests: all ${_total} that tests/NN-name/*.cpp declare (${_lessons} lessons) are in CTest")
