// The vibrofric tool's own source (lib/tool/main.cpp) with its main() renamed, so that the
// argument-parsing fuzz target (fuzz_tool.cpp) can run the real command line in process.
#define main vibrofric_tool_main
#include "../../lib/tool/main.cpp"
