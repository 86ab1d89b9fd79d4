# The parts that need more than the library: the Python module and the test suites. Each
# option is AUTO (the default: built when what it needs is installed, otherwise left out with
# one line saying what to install), ON (required: what is missing is an error) or OFF.

function(pcskeleton_optional_part option description)
  set(${option} AUTO CACHE STRING "${description}: AUTO (when what it needs is installed), ON or OFF")
  set_property(CACHE ${option} PROPERTY STRINGS AUTO ON OFF)
endfunction()

# `mode`: REQUIRED, AUTO or OFF, from the option's value.
function(pcskeleton_part_mode option mode)
  string(TOUPPER "${${option}}" value)
  if(value STREQUAL "AUTO")
    set(${mode} AUTO PARENT_SCOPE)
  elseif(${option})
    set(${mode} REQUIRED PARENT_SCOPE)
  else()
    set(${mode} OFF PARENT_SCOPE)
  endif()
endfunction()

# After an AUTO part's search: the option becomes ON or OFF for the rest of the build, and a
# part left out says what to install and how to require it.
macro(pcskeleton_decide_part option found what install)
  if(${found})
    set(${option} ON)
  else()
    set(${option} OFF)
    message(STATUS "pcskeleton: ${what} left out: install ${install} (Debian), or -D${option}=ON to require it")
  endif()
endmacro()
