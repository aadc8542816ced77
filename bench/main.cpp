// vibrofric_bench: speed and accuracy of every path (issue #5). Flags of its own, before Google
// Benchmark's (--benchmark_filter, --benchmark_out=FILE --benchmark_out_format=json, …):
//   --quick                   fewer inputs and grid points, 10 ms minimum time, one repetition (CI)
//   --accuracy_points=FILE    one CSV row per accuracy path and grid point (bench/README.md)
#include <cstring>
#include <string>
#include <vector>

#include "common.hpp"

namespace vibrofric::bench {
Config& config() {
  static Config c;
  return c;
}
}  // namespace vibrofric::bench

int main(int argc, char** argv) {
  using namespace vibrofric::bench;
  std::vector<char*> rest;
  const char* const points_flag = "--accuracy_points=";
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && std::strcmp(argv[i], "--quick") == 0) {
      config().quick = true;
    } else if (i > 0 && std::strncmp(argv[i], points_flag, std::strlen(points_flag)) == 0) {
      const char* file = argv[i] + std::strlen(points_flag);
      config().points = std::fopen(file, "w");
      if (!config().points) {
        std::fprintf(stderr, "vibrofric_bench: cannot write %s\n", file);
        return 2;
      }
      std::fprintf(config().points, "wave,path,beta,gamma,tags,value,reference,ulp,status\n");
    } else {
      rest.push_back(argv[i]);
    }
  }
  int rest_argc = static_cast<int>(rest.size());
  rest.push_back(nullptr);

  register_accuracy();
  register_speed_double();
  register_speed_long_double();
  register_speed_bin50();
  register_speed_mpfr();
  register_curved();
  register_certify();
  register_rig();
  register_inplane();

  benchmark::Initialize(&rest_argc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_argc, rest.data())) return 2;
  benchmark::AddCustomContext("vibrofric_mode", config().quick ? "quick" : "full");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (config().points) std::fclose(config().points);
  return 0;
}
