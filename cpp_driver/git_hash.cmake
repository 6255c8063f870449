# Writes OUT, a header with the code version of the source tree SRC as `git describe` gives
# it, run at every build (not only at configure) so that runs never record a stale hash.
# The file is only replaced when the hash changed, so nothing recompiles otherwise.
#   cmake -DSRC=<source dir> -DOUT=<header> -P git_hash.cmake
execute_process(COMMAND git describe --always --dirty --abbrev=12
                WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT hash)
  set(hash "unknown")
endif()
set(text "// Generated at build time by cpp_driver/git_hash.cmake; do not edit.\n#pragma once\n#define SPHJET_GIT_HASH \"${hash}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUT} "${text}")
endif()
