# Warnings apply to our own targets only; third-party headers are included as SYSTEM.
function(magfem_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
