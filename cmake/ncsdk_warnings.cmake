# Warnings and sanitizers live here, in one place, applied per target with ncsdk_set_warnings().
add_library(ncsdk_build_flags INTERFACE)
target_compile_options(ncsdk_build_flags INTERFACE -Wall -Wextra -Wpedantic -Wconversion -Wshadow)
if(NCSDK_WERROR)
  target_compile_options(ncsdk_build_flags INTERFACE -Werror)
endif()
if(NCSDK_SANITIZE)
  target_compile_options(ncsdk_build_flags INTERFACE -fsanitize=address,undefined
                                                     -fno-sanitize-recover=undefined
                                                     -fno-omit-frame-pointer)
  target_link_options(ncsdk_build_flags INTERFACE -fsanitize=address,undefined)
endif()

function(ncsdk_set_warnings target)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:ncsdk_build_flags>)
endfunction()
