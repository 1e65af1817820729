// pathspace help [COMMAND], pathspace --help, pathspace COMMAND --help: built from the commands
// that registered themselves (app/command.h), so every command is listed with its options.
#include <iostream>
#include <sstream>
#include "command.h"

namespace ps {
namespace {

const char* const kExitStatus = R"(exit status: 0 on success, 1 on bad input (the message names file, line and problem),
2 on a bad command line: an unknown option, a number out of range (NaN and Inf never pass),
or an output path that cannot be written (missing folder, a folder, an unknown extension)
or that is one of the command's inputs (the scene, its meshes, the reference: no output
overwrites an input); every output path is checked before anything is rendered.
)";

constexpr size_t kSummaryColumn = 37, kWidth = 96;

// "  pathspace SYNOPSIS" and the summary from column 37, word-wrapped at 96 columns; a synopsis
// too long for that puts the summary on the next line.
void synopsisLine(std::ostream& os, const std::string& synopsis, const std::string& summary) {
    std::string line = "  pathspace " + synopsis;
    if (line.size() + 2 > kSummaryColumn) {
        os << line << "\n";
        line.clear();
    }
    line.resize(kSummaryColumn, ' ');
    std::istringstream words(summary);
    std::string word;
    bool first = true;
    while (words >> word) {
        if (!first && line.size() + 1 + word.size() > kWidth) {
            os << line << "\n";
            line = std::string(kSummaryColumn, ' ') + word;
        } else {
            line += (first ? "" : " ") + word;
        }
        first = false;
    }
    os << line << "\n";
}

int runHelp(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cout << programHelp();
        return 0;
    }
    if (args.size() > 1) throw UsageError("'help' takes one command name");
    const Command* command = findCommand(args[0]);
    if (!command) throw UsageError("unknown command '" + args[0] + "'");
    std::cout << commandHelp(*command);
    return 0;
}

}  // namespace

std::string programHelp() {
    std::ostringstream os;
    os << "pathspace - a light transport course renderer\n\nusage:\n";
    bool algorithms = false;
    for (const Command& c : commandList()) {
        synopsisLine(os, c.synopsis, c.summary);
        algorithms = algorithms || c.takesAlgorithms;
    }
    synopsisLine(os, "--help", "this text");
    for (const Command& c : commandList())
        if (!c.usage.empty()) os << "\n" << c.usage;
    if (algorithms) {
        os << "\n";
        listAlgorithms(os);
    }
    os << "\n" << kExitStatus;
    return os.str();
}

std::string commandHelp(const Command& c) {
    std::ostringstream os;
    os << "usage: pathspace " << c.synopsis << "\n  " << c.summary << "\n";
    if (!c.usage.empty()) os << "\n" << c.usage;
    if (c.takesAlgorithms) {
        os << "\n";
        listAlgorithms(os);
    }
    os << "\n" << kExitStatus;
    return os.str();
}

namespace {
Command helpCommand() {
    Command c;
    c.name = "help";
    c.order = 90;
    c.synopsis = "help [COMMAND]";
    c.summary = "this text, or the options of one command";
    c.run = runHelp;
    return c;
}
}  // namespace

PS_REGISTER_COMMAND(helpCommand());

}  // namespace ps
