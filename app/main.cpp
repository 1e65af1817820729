// pathspace: the command-line front end. The commands register themselves (app/command.h,
// one file each in app/commands/); this file only finds the one asked for and turns errors into
// messages and exit statuses. `pathspace --help` lists the commands.
#include <iostream>
#include <string>
#include <vector>
#include "command.h"
#include "errors.h"
#include "passive_wait.h"

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h") {
            std::cout << ps::programHelp();
            return args.empty() ? 2 : 0;
        }
        const ps::Command* command = ps::findCommand(args[0]);
        if (!command) throw ps::UsageError("unknown command '" + args[0] + "'");
        args.erase(args.begin());
        for (const auto& a : args)
            if (a == "--help" || a == "-h") {
                std::cout << ps::commandHelp(*command);
                return 0;
            }
        return command->run(args);
    } catch (const ps::UsageError& e) {
        // A message of several lines (an expression and a caret under its fault) keeps them
        // together and says the rest on a line of its own.
        const std::string what = e.what();
        std::cerr << "pathspace: " << what << (what.find('\n') == std::string::npos ? " " : "\n")
                  << "(run 'pathspace --help' for usage)\n";
        return 2;
    } catch (const ps::InputError& e) {
        std::cerr << "pathspace: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "pathspace: internal error: " << e.what() << "\n";
        return 3;
    }
}
