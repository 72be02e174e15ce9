// carom: the command-line tool (command_line.cpp builds the command line and runs the verb).
#include "commands/command_line.hpp"

int main(int argc, char** argv) { return carom::cli::run_command_line(argc, argv); }
