# How the grader (tools/grade) builds the test program of one lesson from a submission: compile
# the submission's files of that lesson (target objects; the grader then checks them, objcheck.h),
# link them with the prepared tree's objects (target lesson_tests). Copied into the tree as
# rules/lesson.mk; rules/NN.mk (written by cmake/grader_tree.cmake) holds lesson NN's compiler
# and flags, exactly as the reference build compiled that lesson.
#   make -f TREE/rules/lesson.mk TREE=TREE LESSON=NN SRCDIR=DIR SOURCES='a.cpp b.cpp' objects|lesson_tests
include $(TREE)/rules/$(LESSON).mk

OBJECTS := $(SOURCES:.cpp=.o)
# What the reference build links into every lesson's test program: main() and the grader's result
# channel, this lesson's graded tests, every lesson's reference but this one's (in the sandbox
# that folder is not even there), every lesson's plumbing.
PREBUILT := $(wildcard $(TREE)/lib/main/*.o) $(wildcard $(TREE)/lib/$(LESSON)/tests/*.o) \
            $(filter-out $(TREE)/lib/$(LESSON)/%,$(wildcard $(TREE)/lib/*/reference/*.o)) \
            $(wildcard $(TREE)/lib/*/plumbing/*.o)
ARCHIVES := $(TREE)/lib/test_support.a $(TREE)/lib/framework.a

objects: $(OBJECTS)

# The course's objects and the archive members they need come first: where the submission's
# objects hold a copy of the same inline function or template, the linker keeps the first, the
# course's. The archives again after the submission's objects, for what only they need. No
# executable stack, whatever an object asks for.
lesson_tests: $(OBJECTS)
	$(CXX) $(LDFLAGS) -Wl,-z,noexecstack -o $@ $(PREBUILT) $(ARCHIVES) $(OBJECTS) $(ARCHIVES) $(LIBS)

%.o: $(SRCDIR)/%.cpp
	$(CXX) $(CXXFLAGS) $(INCLUDES) -c $< -o $@

.PHONY: objects
