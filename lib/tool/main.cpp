// vibrofric: the command-line tool. μ̄/μ0 (Eq. 15), Ψ_w (Eq. 12), sweeps, physical inputs
// (Eqs. 1, 5, 14) and the claims check. Bad input: one line on stderr, exit 2; solver failure: 1.
// The commands live in cli.cpp (the table and the command line) and cmd_*.cpp.
#include "cli.hpp"

int main(int argc, char** argv) { return vibrofric::tool::run_tool(argc, argv); }
