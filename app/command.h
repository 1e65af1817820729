// The program's commands register themselves the way integrators do (framework/registry.h): each
// command's file fills a Command, field by field, and registers it at namespace scope,
//   PS_REGISTER_COMMAND(renderCommand());
// and main.cpp only looks the name up. `pathspace --help` and `pathspace help COMMAND` are built
// from the same entries, so a new command is documented as soon as it exists. A command parses
// its arguments in one function (into a struct of its options) and runs in another.
#pragma once
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include "integrator.h"
#include "numbers.h"
#include "registry.h"
#include "stopwatch.h"
#include "vecmath.h"

namespace ps {

class Scene;
struct Image;

struct Command {
    std::string name;              // what the user types: pathspace NAME ...
    int order = 0;                 // place in `pathspace --help` (smaller first)
    std::string synopsis;          // "render SCENE [options]"
    std::string summary;           // one line: what it does
    std::string usage;             // its options, one per line or two, ending in a newline
    bool takesAlgorithms = false;  // it makes integrators: its help lists them and the algorithm options
    int (*run)(const std::vector<std::string>& args) = nullptr;  // exit status
};

// The commands (Registry<Command>), in `order`.
std::vector<Command> commandList();
// nullptr for a name no command has.
const Command* findCommand(const std::string& name);

// In a command's .cpp at namespace scope, with a Command made field by field.
#define PS_REGISTER_COMMAND(command)                                                                                 \
    namespace {                                                                                                      \
    const ::ps::Command psCommand = command;                                                                         \
    [[maybe_unused]] const bool psCommandRegistered = ::ps::Registry<::ps::Command>::add(psCommand.name, psCommand); \
    }

// A bad command line: main prints "pathspace: MESSAGE (run 'pathspace --help' for usage)" and
// exits with status 2. (Bad input files throw InputError instead: status 1.)
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The value of the option at args[i] (it is args[i + 1]; i moves onto it), else UsageError
// "option OPT needs a value". Every command's option loop reads its values with it.
inline const std::string& optionValue(const std::vector<std::string>& args, size_t& i) {
    if (i + 1 >= args.size()) throw UsageError("option " + args[i] + " needs a value");
    return args[++i];
}

// The whole value of option opt as a number, else UsageError "option OPT needs a number, got 'S'".
template <class T>
T parseNumber(const std::string& opt, const std::string& s) {
    T v{};
    if (parseWhole(s, v) != std::errc()) throw UsageError("option " + opt + " needs a number, got '" + s + "'");
    return v;
}

// parseNumber and a range. parseAtLeast: UsageError "option OPT must be at least MIN, got 'S'";
// parseWithin: "option OPT must be from LO to HI, got 'S'" (a NaN is never within).
template <class T>
std::string numberText(T v) {
    std::ostringstream os;
    os << v;
    return os.str();
}
template <class T>
T parseAtLeast(const std::string& opt, const std::string& s, T min) {
    const T v = parseNumber<T>(opt, s);
    if (!(v >= min)) throw UsageError("option " + opt + " must be at least " + numberText(min) + ", got '" + s + "'");
    return v;
}
template <class T>
T parseWithin(const std::string& opt, const std::string& s, T lo, T hi) {
    const T v = parseNumber<T>(opt, s);
    if (!(v >= lo && v <= hi))
        throw UsageError("option " + opt + " must be from " + numberText(lo) + " to " + numberText(hi) + ", got '" + s +
                         "'");
    return v;
}
// --threads: at most this many (OpenMP would try to start them all; the image does not depend on it).
constexpr int kMaxThreads = 1024;
// A floating-point option that must be finite and positive (--time): UsageError
// "option OPT must be a positive number, got 'S'" for 0, a negative number, nan or inf.
double parsePositive(const std::string& opt, const std::string& s);
// --clock: "wall" or "cpu" (framework/stopwatch.h); UsageError for anything else.
TimeClock parseClockOption(const std::string& s);

// Output paths are checked right after the options are parsed, before a scene is loaded or a
// sample rendered: a bad path costs nothing and leaves nothing behind. Every command that
// writes files calls these (one place for the rules):
//   - a file: not a folder (nor a name ending in '/'), its folder exists and is a folder, the
//     file can be opened for writing (tried: an existing file is opened for appending and left
//     as it was, a new one is made and removed again), and its extension is one of
//     `extensions` (lower case with the dot, any case accepted; empty: any name);
//   - two outputs of one command must not be the same file, and no output may be one of the
//     command's inputs (the scene file, the reference image, ...): compared as files, not as
//     spellings (sameFile), so "./x", a symbolic or a hard link to x are x;
//   - a folder (checkOutputFolder): an existing folder in which each of `files` passes the
//     file check, or a path whose nearest existing ancestor is a folder in which the missing
//     folders can be made (tried, and removed again).
// A problem throws UsageError "OPTION 'PATH': PROBLEM", e.g.
//   option --out 'nodir/x.png': folder 'nodir' does not exist
//   option --csv 'a.pfm': is the reference image 'a.pfm' (--reference): an output must not
//   overwrite an input
struct OutputFile {
    std::string option;                   // "--out"
    std::string path;                     // as the user gave it (or its default)
    std::vector<std::string> extensions;  // e.g. imageExtensions() (image.h) or {".pfm"}; {} = any
};
struct InputFile {
    std::string what;    // "the scene file", "the reference image"
    std::string path;    // as the user gave it
    std::string option;  // the option that named it ("--reference"), if any
};
void checkOutputFiles(const std::vector<OutputFile>& files, const std::vector<InputFile>& inputs = {});
void checkOutputFolder(const std::string& option, const std::string& folder, const std::vector<std::string>& files,
                       const std::vector<InputFile>& inputs = {});
// Only the rule that no output is an input, for inputs known later: the meshes and material
// libraries a scene file names (Scene::inputFiles), checked after loading, before rendering.
void checkNotInputs(const std::vector<OutputFile>& files, const std::vector<InputFile>& inputs);
// The scene's own files (Scene::inputFiles) as inputs: "the scene file", "a file the scene file reads".
std::vector<InputFile> sceneInputs(const Scene& scene);
// Whether paths a and b name the same file: an existing file by identity (device and inode:
// symbolic and hard links, "./x" and "x"); a file that does not exist yet by its folder's identity
// and its name (a dangling symbolic link by where it points). Never a device or a pipe: they take
// any number of outputs.
bool sameFile(const std::string& a, const std::string& b);

// A reference image (--reference) for a scene: read with the scene's size (refused from its
// header if it differs, before its pixels are decoded: image.h), and refused if a pixel is NaN or
// Inf (every error against it would be NaN: the log would hold nothing). InputError naming the
// file, the first such pixel and how many there are.
Image readReference(const std::string& path, const Scene& scene);

// stem("dir/a.scene") = "dir/a", baseName("dir/a.scene") = "a.scene", splitList("a,b,,c") = {a, b, c}.
std::string stem(const std::string& path);
std::string baseName(const std::string& path);
std::vector<std::string> splitList(const std::string& s);

// An algorithm option (framework/integrator.h: --NAME VALUE, registered by a lesson, e.g. --paths)
// at args[i]: appends (NAME, VALUE) to options, i moved onto the value, and returns true; its value
// checked now (a bad one: UsageError); false if args[i] names no algorithm option.
bool parseAlgorithmOption(const std::vector<std::string>& args, size_t& i, AlgorithmOptions& options);
// makeIntegrator(algo, options), a bad option (OptionError) turned into a UsageError.
std::unique_ptr<Integrator> makeAlgorithm(const std::string& algo, const AlgorithmOptions& options);
// " (--NAME 'VALUE', ...)" for messages, "" without options.
std::string describeOptions(const AlgorithmOptions& options);
// A render parameter (framework/scene.h: --NAME V1,..,Vn, registered by a lesson, e.g. --elements)
// at args[i]: its values, separated by commas or 'x' ("8x4"), one value standing for all n of
// them; checked now (renderParameterProblem: a bad one is a UsageError naming the option); sets
// values[NAME], i moved onto the value, and returns true; false if args[i] names no render parameter.
using RenderParameterValues = std::map<std::string, std::vector<float>>;
bool parseRenderParameterOption(const std::vector<std::string>& args, size_t& i, RenderParameterValues& values);
// The command line's render parameters over the scene's (RenderSettings::parameters).
void setRenderParameters(const RenderParameterValues& values, RenderSettings& settings);

// One line "pathspace: ALGO leaves out ..." on stderr per piece of work the integrator leaves
// out on this scene (Integrator::leftOut).
void printLeftOut(const std::string& algo, const Integrator& integrator, const Scene& scene);
// "algorithms:" and one line per registered integrator: name and description (marked * where it
// takes an algorithm option), then the algorithm options' help and the render parameters'.
void listAlgorithms(std::ostream& os);
// Whether standard error is a terminal (the default of --progress).
bool stderrIsTerminal();

// The whole help (`pathspace --help`): every command's synopsis and summary, then every
// command's options, the algorithms and the exit status.
std::string programHelp();
// One command's help (`pathspace help NAME`, `pathspace NAME --help`).
std::string commandHelp(const Command& command);

}  // namespace ps
