# RAINTRACE_SANITIZE builds everything with ASan + UBSan; the whole test suite must pass under it.
if(RAINTRACE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
