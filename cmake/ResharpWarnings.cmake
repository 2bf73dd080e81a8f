# Interface targets that carry compile flags, so no flag is set globally.

add_library(resharp_warnings INTERFACE)
add_library(resharp::warnings ALIAS resharp_warnings)
target_compile_options(resharp_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
        -Wno-missing-field-initializers>)  # designated initializers leave defaults on purpose

add_library(resharp_sanitizers INTERFACE)
add_library(resharp::sanitizers ALIAS resharp_sanitizers)
if(RESHARP_SANITIZE)
    target_compile_options(resharp_sanitizers INTERFACE
        -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
    target_link_options(resharp_sanitizers INTERFACE -fsanitize=address,undefined)
endif()
