# One bounded libFuzzer run (ctest fuzz.<target>): a fresh scratch corpus in WORK, the committed
# seeds in SEEDS (read only: libFuzzer adds new inputs to the first directory only), SECONDS of
# fuzzing, inputs up to 4 KiB, 30 s per input. A crash, a sanitizer report, a timeout or a finding
# of the target (it aborts) fails the test; the input is kept as WORK/../<target>-crash-*.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
get_filename_component(name ${FUZZER} NAME)
get_filename_component(artifacts ${WORK} DIRECTORY)
execute_process(
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -max_len=4096 -timeout=30 -rss_limit_mb=4096
          -print_final_stats=1 -artifact_prefix=${artifacts}/${name}- ${WORK} ${SEEDS}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${name}: libFuzzer exited with ${rc} (a finding; the input is in ${artifacts})")
endif()
