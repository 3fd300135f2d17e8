# Writes OUT with the source tree's git revision ("unknown" outside a git checkout), at every build,
# touching the file only when the revision changed (so nothing recompiles needlessly).
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty=+changes
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR revision STREQUAL "")
  set(revision "unknown")
endif()
set(text "// Generated at build time by cmake/git_revision.cmake.\n#pragma once\nnamespace demscale {\ninline constexpr const char* git_revision = \"${revision}\";\n}\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
