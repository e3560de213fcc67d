# One INTERFACE target carries the warning flags, so every library links the same set.
add_library(raintrace_warnings INTERFACE)
target_compile_options(raintrace_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough)
