// commands.h: the subcommands of pcfscope. Each registers its options on the CLI11 app and
// returns the function that runs it once the command line is parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace pcf {

struct Command {
    CLI::App* sub;
    std::function<int()> run;
};

Command addMethodsCommand(CLI::App& app);
Command addTraceCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addTruthCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addStabilityCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addAnimateCommand(CLI::App& app);
Command addVerifyCommand(CLI::App& app);

// `pcfscope` with no arguments: lesson 1 in the window when there is a display, otherwise its
// frames exported into a new folder under pcfscope-frames/ (printed on stdout).
int runMainJob();

}  // namespace pcf
