# RAINTRACE_SANITIZE builds everything with ASan + UBSan; the test suite must pass under it
# (scripts/test.sh leaves out the suites that run whole examples at full size).
if(RAINTRACE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
