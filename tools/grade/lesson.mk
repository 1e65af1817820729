# How the grader (tools/grade) builds the test program of one lesson from a submission: compile
# the submission's files of that lesson, link them with the prepared tree's objects. Copied into
# the tree as rules/lesson.mk; rules/NN.mk (written by cmake/grader_tree.cmake) holds lesson NN's
# compiler and flags, exactly as the reference build compiled that lesson.
#   make -f TREE/rules/lesson.mk TREE=TREE LESSON=NN SRCDIR=DIR SOURCES='a.cpp b.cpp'   (in the build dir)
include $(TREE)/rules/$(LESSON).mk

OBJECTS := $(SOURCES:.cpp=.o)
# What the reference build links into every lesson's test program: every lesson's reference but
# this one's (in the sandbox that folder is not even there), every lesson's plumbing; and this
# lesson's graded tests with their main().
PREBUILT := $(filter-out $(TREE)/lib/$(LESSON)/%,$(wildcard $(TREE)/lib/*/reference/*.o)) \
            $(wildcard $(TREE)/lib/*/plumbing/*.o) $(wildcard $(TREE)/lib/$(LESSON)/tests/*.o) \
            $(TREE)/lib/test_main.o

lesson_tests: $(OBJECTS)
	$(CXX) $(LDFLAGS) -o $@ $(OBJECTS) $(PREBUILT) $(TREE)/lib/test_support.a $(TREE)/lib/framework.a $(LIBS)

%.o: $(SRCDIR)/%.cpp
	$(CXX) $(CXXFLAGS) $(INCLUDES) -c $< -o $@
