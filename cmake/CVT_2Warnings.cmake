# cvt_2_add_warnings(target): the warnings our own targets compile with, never the library's
# INTERFACE target (a user's flags are the user's).
function(cvt_2_add_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive-)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  endif()
endfunction()
