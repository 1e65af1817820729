#include "command.h"
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include "errors.h"
#include "image.h"
#include "scene.h"
#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace ps {

std::vector<Command> commandList() {
    std::vector<Command> list;
    for (const auto& e : Registry<Command>::sorted()) list.push_back(e.value);
    // By order, then by name (std::sort with a total order: libstdc++'s stable_sort trips clang 19's
    // deprecation warning on get_temporary_buffer).
    std::sort(list.begin(), list.end(), [](const Command& a, const Command& b) {
        return a.order != b.order ? a.order < b.order : a.name < b.name;
    });
    return list;
}

const Command* findCommand(const std::string& name) { return Registry<Command>::find(name); }

double parsePositive(const std::string& opt, const std::string& s) {
    const double v = parseNumber<double>(opt, s);
    if (!(v > 0.0) || !std::isfinite(v))
        throw UsageError("option " + opt + " must be a positive number, got '" + s + "'");
    return v;
}

TimeClock parseClockOption(const std::string& s) {
    TimeClock c;
    if (!parseClock(s, c)) throw UsageError("option --clock must be 'wall' or 'cpu', got '" + s + "'");
    return c;
}

namespace {
namespace fs = std::filesystem;

[[noreturn]] void badOutput(const std::string& option, const std::string& path, const std::string& problem) {
    throw UsageError("option " + option + " '" + path + "': " + problem);
}

// errno's text, or `otherwise` when the library left errno unset.
std::string reason(int err, const std::string& otherwise) {
    return err != 0 ? std::string(std::strerror(err)) : otherwise;
}

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string listed(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
    return out;
}

// Where path leads: through dangling symbolic links to the file they would create (at most 40
// links, as the system follows them); an existing file or a plain name is returned as it is.
fs::path followDangling(fs::path p) {
    std::error_code ec;
    for (int i = 0; i < 40; ++i) {
        if (!fs::is_symlink(fs::symlink_status(p, ec)) || fs::exists(p, ec)) return p;
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) return p;
        p = target.is_absolute() ? target : (p.has_parent_path() ? p.parent_path() : fs::path(".")) / target;
    }
    return p;
}
void checkOutputFile(const OutputFile& f) {
    if (f.path.empty()) badOutput(f.option, f.path, "empty file name");
    const fs::path p(f.path);
    std::error_code ec;
    if (!p.has_filename() || fs::is_directory(p, ec)) badOutput(f.option, f.path, "is a folder, not a file name");
    if (!f.extensions.empty()) {
        const std::string ext = lowerExtension(p);
        if (std::find(f.extensions.begin(), f.extensions.end(), ext) == f.extensions.end())
            badOutput(
                f.option, f.path,
                (ext.empty() ? std::string("no extension") : "unknown extension '" + p.extension().string() + "'") +
                    " (use " + listed(f.extensions) + ")");
    }
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::exists(folder, ec)) badOutput(f.option, f.path, "folder '" + folder.string() + "' does not exist");
    if (!fs::is_directory(folder, ec)) badOutput(f.option, f.path, "'" + folder.string() + "' is not a folder");
    // Try it: append (an existing file keeps its bytes), and remove what did not exist before
    // (through a dangling symbolic link that is the file it points to, not the link).
    const fs::path made = followDangling(p);
    const bool existed = fs::exists(made, ec);
    errno = 0;
    std::ofstream probe(f.path, std::ios::binary | std::ios::app);
    const int err = errno;
    if (!probe) badOutput(f.option, f.path, "cannot be written (" + reason(err, "cannot open for writing") + ")");
    probe.close();
    if (!existed) fs::remove(made, ec);
}
}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    const fs::path pa = followDangling(a), pb = followDangling(b);
    const bool ea = fs::exists(pa, ec), eb = fs::exists(pb, ec);
    // A device or a pipe (/dev/null, /dev/full) takes any number of outputs: only two regular files
    // can be one file (and the standard libraries disagree on equivalent() for devices).
    if (ea && eb) return fs::is_regular_file(pa, ec) && fs::is_regular_file(pb, ec) && fs::equivalent(pa, pb, ec);
    if (ea != eb) return false;
    if (pa.filename() != pb.filename()) return false;
    const fs::path fa = pa.has_parent_path() ? pa.parent_path() : fs::path(".");
    const fs::path fb = pb.has_parent_path() ? pb.parent_path() : fs::path(".");
    return fs::exists(fa, ec) && fs::exists(fb, ec)
               ? fs::equivalent(fa, fb, ec)
               : fs::absolute(fa, ec).lexically_normal() == fs::absolute(fb, ec).lexically_normal();
}

void checkNotInputs(const std::vector<OutputFile>& files, const std::vector<InputFile>& inputs) {
    for (const OutputFile& f : files)
        for (const InputFile& in : inputs)
            if (sameFile(f.path, in.path))
                badOutput(f.option, f.path,
                          "is " + in.what + " '" + in.path + "'" + (in.option.empty() ? "" : " (" + in.option + ")") +
                              ": an output must not overwrite an input");
}

void checkOutputFiles(const std::vector<OutputFile>& files, const std::vector<InputFile>& inputs) {
    for (size_t i = 0; i < files.size(); ++i) {
        checkOutputFile(files[i]);
        for (size_t j = 0; j < i; ++j)
            if (sameFile(files[j].path, files[i].path))
                badOutput(files[i].option, files[i].path,
                          "is also the file of " + files[j].option + " ('" + files[j].path + "')");
    }
    checkNotInputs(files, inputs);
}

std::vector<InputFile> sceneInputs(const Scene& scene) {
    std::vector<InputFile> inputs;
    for (size_t i = 0; i < scene.inputFiles.size(); ++i)
        inputs.push_back({i == 0 ? "the scene file" : "a file the scene file reads", scene.inputFiles[i], ""});
    return inputs;
}

void checkOutputFolder(const std::string& option, const std::string& folder, const std::vector<std::string>& files,
                       const std::vector<InputFile>& inputs) {
    if (folder.empty()) badOutput(option, folder, "empty folder name");
    std::error_code ec;
    const fs::path p = fs::path(folder).lexically_normal();
    if (fs::exists(p, ec)) {
        if (!fs::is_directory(p, ec)) badOutput(option, folder, "exists and is not a folder");
        std::vector<OutputFile> inside;
        for (const std::string& name : files) inside.push_back({option, (p / name).string(), {}});
        checkOutputFiles(inside, inputs);
        return;
    }
    // The nearest existing ancestor must be a folder in which the first missing one can be made.
    fs::path missing = p, parent;
    for (;;) {
        parent = missing.has_parent_path() ? missing.parent_path() : fs::path(".");
        if (fs::exists(parent, ec) || parent == missing) break;
        missing = parent;
    }
    if (!fs::is_directory(parent, ec)) badOutput(option, folder, "'" + parent.string() + "' is not a folder");
    if (!fs::create_directory(missing, ec))
        badOutput(option, folder,
                  "cannot make folder '" + missing.string() + "' (" + (ec ? ec.message() : "unknown reason") + ")");
    fs::remove(missing, ec);
}

Image readReference(const std::string& path, const Scene& scene) {
    Image ref = readImage(path, scene.camera.width(), scene.camera.height());
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < ref.pixels.size(); ++i) {
        const Color& c = ref.pixels[i];
        if (std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) continue;
        if (bad++ == 0) first = i;
    }
    if (bad > 0) {
        const Color& c = ref.pixels[first];
        std::ostringstream os;
        os << "pixel (" << first % size_t(ref.width) << ", " << first / size_t(ref.width) << ") is " << c.r << " "
           << c.g << " " << c.b << ": a reference must be finite (" << bad << " of " << ref.pixels.size()
           << " pixels are NaN or Inf)";
        throw InputError(path, 0, os.str());
    }
    return ref;
}

std::string stem(const std::string& path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
    return path.substr(0, dot);
}

std::string baseName(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s + ",") {
        if (c == ',') {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    return out;
}

void printLeftOut(const std::string& algo, const Integrator& integrator, const Scene& scene) {
    for (const std::string& line : integrator.leftOut(scene))
        std::cerr << "pathspace: " << algo << " leaves out " << line << "\n";
}

namespace {
// A render parameter's value names as the command line writes them: "N M" in a scene file is N,M.
std::string commandLineValueNames(const RenderParameter& p) {
    std::string names = p.valueNames;
    std::replace(names.begin(), names.end(), ' ', ',');
    return names;
}
}  // namespace

void listAlgorithms(std::ostream& os) {
    const std::vector<IntegratorInfo> list = integratorList();
    size_t width = 0;
    for (const auto& i : list) width = std::max(width, i.name.size());
    os << "algorithms:\n";
    for (const auto& i : list)
        os << "  " << i.name << std::string(width + 2 - i.name.size(), ' ') << i.description
           << (takesAlgorithmOption(i.name) ? " *" : "") << "\n";
    const std::vector<std::string> options = algorithmOptionNames();
    if (!options.empty()) {
        std::string names;
        for (const std::string& o : options) names += (names.empty() ? "--" : ", --") + o;
        os << "  (* also takes " << names << ")\n\nalgorithm options (render, converge, pyramid):\n";
        for (const auto& e : Registry<AlgorithmOption>::sorted()) os << e.value.help;
    }
    const auto parameters = Registry<RenderParameter>::sorted();
    if (parameters.empty()) return;
    os << "\nrender parameters (render, converge, pyramid): the scene's 'render NAME V1 .. Vn' sets them,\n"
          "--NAME V1,..,Vn overrides it (one value stands for all n; 'x' separates too: 16x8):\n";
    for (const auto& e : parameters) {
        std::string left = "  --" + e.name + " " + commandLineValueNames(e.value);
        left.resize(std::max<size_t>(left.size() + 2, 21), ' ');
        os << left << e.value.help << "\n";
    }
}

bool parseAlgorithmOption(const std::vector<std::string>& args, size_t& i, AlgorithmOptions& options) {
    const std::string& a = args[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0) return false;
    const AlgorithmOption* option = Registry<AlgorithmOption>::find(a.substr(2));
    if (!option) return false;
    const std::string& value = optionValue(args, i);
    try {
        option->check(value);
    } catch (const OptionError& e) { throw UsageError(e.what()); }
    options.push_back({a.substr(2), value});
    return true;
}

std::unique_ptr<Integrator> makeAlgorithm(const std::string& algo, const AlgorithmOptions& options) {
    try {
        return makeIntegrator(algo, options);
    } catch (const OptionError& e) { throw UsageError(e.what()); }
}

std::string describeOptions(const AlgorithmOptions& options) {
    std::string s;
    for (const auto& [name, value] : options) s += (s.empty() ? "" : ", ") + ("--" + name + " '" + value + "'");
    return s.empty() ? s : " (" + s + ")";
}

bool parseRenderParameterOption(const std::vector<std::string>& args, size_t& i, RenderParameterValues& values) {
    const std::string& a = args[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0) return false;
    const std::string name = a.substr(2);
    const RenderParameter* p = Registry<RenderParameter>::find(name);
    if (!p) return false;
    const std::string text = optionValue(args, i);
    const std::string names = commandLineValueNames(*p);
    std::vector<float> v;
    std::string part;
    for (size_t k = 0; k <= text.size(); ++k) {
        if (k < text.size() && text[k] != ',' && text[k] != 'x') {
            part += text[k];
            continue;
        }
        float x = 0.0f;
        if (parseWhole(part, x) != std::errc())
            throw UsageError("option " + a + " needs " + (p->count > 1 ? "numbers (" + names + ")" : "a number") +
                             ", got '" + text + "'");
        v.push_back(x);
        part.clear();
    }
    if (v.size() == 1) v.resize(size_t(p->count), v[0]);  // one value for all of them
    std::string problem = renderParameterProblem(*p, v);
    if (v.size() != size_t(p->count))
        problem = "needs " + std::string(p->count > 1 ? "1 or " + std::to_string(p->count) + " numbers" : "1 number") +
                  " (" + names + ")";
    if (!problem.empty()) throw UsageError("option " + a + " " + problem + ", got '" + text + "'");
    values[name] = v;
    return true;
}

void setRenderParameters(const RenderParameterValues& values, RenderSettings& settings) {
    for (const auto& [name, v] : values) settings.parameters[name] = v;
}

bool stderrIsTerminal() {
#if defined(_WIN32)
    return _isatty(2) != 0;
#else
    return isatty(2) != 0;
#endif
}

}  // namespace ps
