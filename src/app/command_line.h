// command_line.h: pcfscope's whole command line behind one call, so that main.cpp (its own
// target) compiles in a moment and the parser's code is built once, with the rest of app/.
#pragma once

namespace pcf {

// Parses argv, runs the subcommand (or the main job) and returns the process's exit code: 0,
// 2 for bad input or a failed write (one line on stderr), 1 for an internal error.
int runCommandLine(int argc, char** argv);

}  // namespace pcf
