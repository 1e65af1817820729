# Which lessons are built from the student's files (assignments/) and which from the
# reference. Any mix can be built and graded:
#   -DPATHSPACE_STUDENT=""      every lesson from its reference, where there is one (the default)
#   -DPATHSPACE_STUDENT=all     every lesson from assignments/
#   -DPATHSPACE_STUDENT="3;5"   lessons 3 and 5 from assignments/, the rest from their reference
# A lesson's reference is solutions/NN-name/ (the lecturer's repository) or released/NN-name/ (a
# student handout after the lecturer released that lesson's reference: scripts/handout.sh
# --release). A lesson without one is built from assignments/ whatever PATHSPACE_STUDENT says: in
# a handout without a release, every lesson. So `-DPATHSPACE_STUDENT=8` means the same everywhere:
# lesson 8 yours, every other lesson the reference wherever this tree has it.
# -DPATHSPACE_ASSIGNMENTS_DIR=DIR takes the student's files from DIR (a submission) instead of
# assignments/.
set(PATHSPACE_HAVE_SOLUTIONS OFF)
if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/solutions)
  set(PATHSPACE_HAVE_SOLUTIONS ON)
endif()
set(PATHSPACE_STUDENT "" CACHE STRING "lessons built from assignments/: '', 'all' or a list like '3;5'")
set(PATHSPACE_ASSIGNMENTS_DIR "${PROJECT_SOURCE_DIR}/assignments" CACHE PATH "where the student's lesson folders are")

# pathspace_lesson_reference(NAME OUT): the folder of lesson NAME's reference pieces, or "" (none here).
function(pathspace_lesson_reference NAME OUT)
  set(_dir "")
  if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/solutions/${NAME})
    set(_dir ${PROJECT_SOURCE_DIR}/solutions/${NAME})
  elseif(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/released/${NAME})
    set(_dir ${PROJECT_SOURCE_DIR}/released/${NAME})
  endif()
  set(${OUT} "${_dir}" PARENT_SCOPE)
endfunction()

# The lesson folders: lessons/NN-name.
file(GLOB _lesson_paths LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/lessons/[0-9][0-9]-*)
set(PATHSPACE_LESSONS "")
foreach(_p ${_lesson_paths})
  if(IS_DIRECTORY ${_p})
    get_filename_component(_name ${_p} NAME)
    list(APPEND PATHSPACE_LESSONS ${_name})
  endif()
endforeach()

# pathspace_lesson_is_student(NN OUT): TRUE if lesson NN (two digits) comes from the student:
# asked for in PATHSPACE_STUDENT, or without a reference in this tree.
function(pathspace_lesson_is_student NN OUT)
  math(EXPR _n "${NN}")
  set(_is FALSE)
  if(PATHSPACE_STUDENT STREQUAL "all")
    set(_is TRUE)
  else()
    foreach(_s ${PATHSPACE_STUDENT})
      math(EXPR _sn "${_s}")
      if(_sn EQUAL _n)
        set(_is TRUE)
      endif()
    endforeach()
  endif()
  if(NOT _is)
    file(GLOB _named LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/lessons/${NN}-*)
    set(_ref "")
    foreach(_p ${_named})
      get_filename_component(_name ${_p} NAME)
      pathspace_lesson_reference(${_name} _ref)
    endforeach()
    if(NOT _ref)
      set(_is TRUE)
    endif()
  endif()
  set(${OUT} ${_is} PARENT_SCOPE)
endfunction()

# pathspace_lesson_sources(NAME PIECES PLUMBING): the .cpp files of lesson NAME (e.g.
# 01-monte-carlo). PLUMBING: the lesson's own code, lessons/NAME/*.cpp (integrator registration,
# task loops: the same for everyone). PIECES: what the student writes, from the student's folder
# or the reference (solutions/NAME/*.cpp, or released/NAME/*.cpp in a handout), as chosen above. A file in the student's folder with
# the name of a plumbing file (a submission made from an older handout) is left out: the
# lesson's wins.
function(pathspace_lesson_sources NAME PIECES PLUMBING)
  string(SUBSTRING ${NAME} 0 2 _nn)
  pathspace_lesson_is_student(${_nn} _student)
  if(_student)
    set(_dir ${PATHSPACE_ASSIGNMENTS_DIR}/${NAME})
    set(_from "student (${_dir})")
    pathspace_lesson_reference(${NAME} _ref)
    if(NOT _ref)
      set(_from "student, no reference here (${_dir})")
    endif()
  else()
    pathspace_lesson_reference(${NAME} _dir)
    set(_from "reference")
    if(NOT PATHSPACE_HAVE_SOLUTIONS)
      set(_from "released reference (${_dir})")
    endif()
  endif()
  file(GLOB _files CONFIGURE_DEPENDS ${_dir}/*.cpp)
  if(NOT _files)
    message(FATAL_ERROR "lesson ${NAME}: no .cpp files in ${_dir}")
  endif()
  file(GLOB _plumbing CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/lessons/${NAME}/*.cpp)
  set(_pieces "")
  foreach(_f ${_files})
    get_filename_component(_base ${_f} NAME)
    if(EXISTS ${PROJECT_SOURCE_DIR}/lessons/${NAME}/${_base})
      message(STATUS "lesson ${NAME}: ${_f} left out (lessons/${NAME}/${_base} is the lesson's own)")
    else()
      list(APPEND _pieces ${_f})
    endif()
  endforeach()
  message(STATUS "lesson ${NAME}: ${_from}")
  set(${PIECES} ${_pieces} PARENT_SCOPE)
  set(${PLUMBING} ${_plumbing} PARENT_SCOPE)
endfunction()

# pathspace_add_lesson(NAME): lesson NAME's code as object libraries: lesson_NN (the pieces, the
# student's or the reference's) and, if the lesson has plumbing, lesson_NN_plumbing. Object
# files, not archives: the integrators they register (PS_REGISTER_INTEGRATOR) must always be
# linked. Two libraries so that the grader's prepared tree (cmake/grader.cmake) can ship the
# plumbing compiled and the reference pieces apart from it.
function(pathspace_add_lesson NAME)
  string(SUBSTRING ${NAME} 0 2 NN)
  pathspace_lesson_sources(${NAME} _pieces _plumbing)
  add_library(lesson_${NN} OBJECT ${_pieces})
  target_link_libraries(lesson_${NN} PUBLIC pathspace_framework_core)
  if(_plumbing)
    add_library(lesson_${NN}_plumbing OBJECT ${_plumbing})
    target_link_libraries(lesson_${NN}_plumbing PUBLIC pathspace_framework_core)
  endif()
endfunction()

# pathspace_lessons: the code of lessons 2 and up (integrators and what they need), linked into
# the program and every test as object files. Lessons 0 and 1 are part of the framework itself
# (framework/CMakeLists.txt).
function(pathspace_add_lesson_libraries)
  add_library(pathspace_lessons INTERFACE)
  foreach(L ${PATHSPACE_LESSONS})
    string(SUBSTRING ${L} 0 2 NN)
    if(NN STREQUAL "00" OR NN STREQUAL "01")
      continue()
    endif()
    pathspace_add_lesson(${L})
    foreach(_t lesson_${NN} lesson_${NN}_plumbing)
      if(TARGET ${_t})
        target_sources(pathspace_lessons INTERFACE $<TARGET_OBJECTS:${_t}>)
        target_link_libraries(pathspace_lessons INTERFACE ${_t})
      endif()
    endforeach()
  endforeach()
  target_link_libraries(pathspace_lessons INTERFACE pathspace_framework)
endfunction()
