# Warnings for the project's own targets (not for consumers of the package).
function(mrpt_evidential_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
