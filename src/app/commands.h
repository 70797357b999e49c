// commands.h: the subcommands of pcfscope. Each registers its options on the CLI11 app and
// returns the function that runs it once the command line is parsed.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace pcf {

struct Command {
    CLI::App* sub;
    std::function<int()> run;
};

Command addMethodsCommand(CLI::App& app);
Command addTraceCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);

// `pcfscope` with no arguments.
int runMainJob();

}  // namespace pcf
