# One INTERFACE target carries the warning flags, so every library links the same set.
add_library(raintrace_warnings INTERFACE)
target_compile_options(raintrace_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough)
# CI builds with RAINTRACE_WERROR=ON: a warning in raintrace's own code fails the build. Headers
# of the dependencies are system headers (/usr/include), whose warnings GCC does not report.
if(RAINTRACE_WERROR)
  target_compile_options(raintrace_warnings INTERFACE -Werror)
endif()
