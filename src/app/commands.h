// commands.h: the subcommands of pcfscope. Each registers its options on the CLI11 app and
// returns the function that runs it once the command line is parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace pcf {

struct Command {
    CLI::App* sub;
    std::function<int()> run;
    // Every check `run` makes before it starts work, and nothing else (no GL, no output): what
    // the fuzz targets drive with random command lines. Empty for commands without one.
    std::function<void()> check = nullptr;
};

Command addMethodsCommand(CLI::App& app);
Command addTraceCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addTruthCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addStabilityCommand(CLI::App& app);
Command addAdviseCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addAnimateCommand(CLI::App& app);
Command addVerifyCommand(CLI::App& app);
Command addLessonCommand(CLI::App& app);  // `lesson check FILE`
Command addPickCommand(CLI::App& app);    // `pick LESSON --step S --pixel X,Y`
Command addExerciseCommand(CLI::App& app);

// `pcfscope verify DIR` with the default envelope precision: 0 all inside, 1 some outside;
// throws UsageError, InputError or ImageError for bad input (the fuzz targets' entry).
int verifyFolder(const std::string& dir);

// `pcfscope` with no arguments: lesson 1 in the window when there is a display, otherwise its
// frames exported into a new folder under pcfscope-frames/ (printed on stdout).
int runMainJob();

}  // namespace pcf
