# RAINTRACE_SANITIZE builds everything with ASan + UBSan; the test suite must pass under it
# (scripts/test.sh leaves out the suites that run whole examples at full size).
# -O1 -g1 (after the build type's -O2 -g, so they win): half the compile time of -O2 -g under the
# sanitizers (33 against 62 CPU s for cli/simulate_command.cpp), with the line tables the
# sanitizers' stack traces need.
if(RAINTRACE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
                      -O1 -g1)
  add_link_options(-fsanitize=address,undefined)
endif()
