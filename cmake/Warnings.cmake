# mx_set_warnings(target): the project's warning policy (-Wall -Wextra -Wpedantic -Wshadow
# -Wnon-virtual-dtor, -Werror in CI).
function(mx_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(MX_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
