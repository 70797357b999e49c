// pcfscope: the program (docs/user-guide.md); app/command_line.cpp holds the command line.
#include "app/command_line.h"

int main(int argc, char** argv) { return pcf::runCommandLine(argc, argv); }
