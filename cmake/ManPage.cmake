# pcskeleton_man_page(TARGET SUMMARY COMPONENT): TARGET's man page, made from its --help and
# --version by help2man (package help2man) and installed with COMPONENT, for the Debian
# packages (cmake/DebianPackages.cmake); left out where help2man is missing.
find_program(HELP2MAN_PROGRAM help2man)
find_program(GZIP_PROGRAM gzip)

function(pcskeleton_man_page target summary component)
  if(NOT HELP2MAN_PROGRAM OR NOT GZIP_PROGRAM)
    return()
  endif()
  set(man_page "${CMAKE_CURRENT_BINARY_DIR}/${target}.1")
  add_custom_command(OUTPUT "${man_page}.gz"
    COMMAND "${HELP2MAN_PROGRAM}" --no-info --no-discard-stderr --name "${summary}"
            --output "${man_page}" "$<TARGET_FILE:${target}>"
    COMMAND "${GZIP_PROGRAM}" -9nf "${man_page}"
    DEPENDS ${target}
    COMMENT "Making the man page ${target}.1 with help2man"
    VERBATIM)
  add_custom_target(${target}_man_page ALL DEPENDS "${man_page}.gz")
  install(FILES "${man_page}.gz" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1" COMPONENT ${component})
endfunction()
