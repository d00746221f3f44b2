# Writes the man page patchwork.1 from the built binary's --help (cmake -P, run by
# packaging/CMakeLists.txt after the binary is built):
#   cmake -DPATCHWORK=<built patchwork> -DHELP2MAN=<help2man> -DINCLUDE=<patchwork.h2m>
#         -DWORK_DIR=<scratch folder> -DOUTPUT=<patchwork.1> -P manpage.cmake
# help2man turns `patchwork --help` and `--version` into NAME, SYNOPSIS, DESCRIPTION and OPTIONS;
# this script adds a COMMANDS section made from every subcommand's --help (the subcommands are
# read from the "Subcommands:" list of `patchwork --help`), then the hand-written parts of INCLUDE
# (NAME, the editor, EXIT STATUS, ENVIRONMENT, FILES, SEE ALSO).
cmake_minimum_required(VERSION 3.25)

foreach(var PATCHWORK HELP2MAN INCLUDE WORK_DIR OUTPUT)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "manpage.cmake: -D${var}=... is required")
  endif()
endforeach()

# help2man decodes --help by the locale (its --locale below): the text has UTF-8 (an em dash, Bézier).
set(ENV{LC_ALL} C.UTF-8)

# The help text of `patchwork ARGN --help` as a list of lines; ';', '[' and ']' (which would
# split or join list elements) are kept as the placeholders @SEMI@, @LB@ and @RB@.
function(pw_help_lines out_var)
  execute_process(COMMAND "${PATCHWORK}" ${ARGN} --help
                  OUTPUT_VARIABLE text ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "manpage.cmake: `${PATCHWORK} ${ARGN} --help` failed (${rc}): ${err}")
  endif()
  string(REPLACE ";" "@SEMI@" text "${text}")
  string(REPLACE "[" "@LB@" text "${text}")
  string(REPLACE "]" "@RB@" text "${text}")
  string(REPLACE "\r" "" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()

# roff-escapes help text and puts the placeholders back (inline: no protection of a line start).
function(pw_roff_inline out_var text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REPLACE "@SEMI@" ";" text "${text}")
  string(REPLACE "@LB@" "[" text "${text}")
  string(REPLACE "@RB@" "]" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# roff-escapes a whole line: a leading '.' or '\'' would be a roff request, a leading '[' or '/' a
# help2man include directive.
function(pw_roff out_var text)
  pw_roff_inline(text "${text}")
  if(text MATCHES "^[.'[/]")
    set(text "\\&${text}")
  endif()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# The roff of one "  NAMES [TYPE...] [REQUIRED]" column of CLI11's help: option names bold,
# positional names italic, the rest (type, range, default) italic, REQUIRED as "(required)".
function(pw_roff_term out_var column is_positional)
  set(required "")
  if(column MATCHES "^(.*) REQUIRED( .*)?$")
    set(column "${CMAKE_MATCH_1}${CMAKE_MATCH_2}")
    set(required " (required)")
  endif()
  set(rest "")
  if(column MATCHES "^([^ ]+) (.+)$")
    set(column "${CMAKE_MATCH_1}")
    pw_roff_inline(rest "${CMAKE_MATCH_2}")
    set(rest " \\fI${rest}\\fR")
  endif()
  pw_roff(names "${column}")
  if(is_positional)
    set(term "\\fI${names}\\fR")
  else()
    string(REPLACE "," "\\fR, \\fB" names "${names}")
    set(term "\\fB${names}\\fR")
  endif()
  set(${out_var} "${term}${rest}${required}" PARENT_SCOPE)
endfunction()

# The subcommands, in the order `patchwork --help` lists them.
pw_help_lines(main_lines)
set(commands "")
set(section "")
foreach(line IN LISTS main_lines)
  if(line MATCHES "^([A-Za-z][A-Za-z ]*):$")
    set(section "${CMAKE_MATCH_1}")
  elseif(section STREQUAL "Subcommands" AND line MATCHES "^  ([^ ]+)")
    list(APPEND commands "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT commands)
  message(FATAL_ERROR "manpage.cmake: no \"Subcommands:\" list in `${PATCHWORK} --help`")
endif()

# [COMMANDS]: one subsection per subcommand, its options as tagged paragraphs (-h,--help left out:
# every command has it).
set(roff "[COMMANDS]\nEvery command also takes \\fB\\-h\\fR, \\fB\\-\\-help\\fR.\n")
foreach(command IN LISTS commands)
  pw_help_lines(lines ${command})
  set(section "")
  set(summary "")
  set(usage "patchwork ${command}")
  set(body "")
  set(skip_entry FALSE)
  foreach(line IN LISTS lines)
    if(line MATCHES "^Usage: (.*)$")
      set(usage "${CMAKE_MATCH_1}")
      string(REPLACE "${PATCHWORK} " "patchwork " usage "${usage}")
      string(REGEX REPLACE "^[^ ]*patchwork " "patchwork " usage "${usage}")
    elseif(line MATCHES "^([A-Za-z][A-Za-z ]*):$")
      set(section "${CMAKE_MATCH_1}")
    elseif(section STREQUAL "" AND NOT line STREQUAL "")
      pw_roff(text "${line}")
      string(APPEND summary "${text}\n")
    elseif(line MATCHES "^  ([^ ].*)$")
      # "  NAMES TYPE...   Description": the column ends at the first run of two spaces.
      set(entry "${CMAKE_MATCH_1}")
      string(FIND "${entry}" "  " split)
      if(split EQUAL -1)
        set(column "${entry}")
        set(description "")
      else()
        string(SUBSTRING "${entry}" 0 ${split} column)
        string(SUBSTRING "${entry}" ${split} -1 description)
        string(STRIP "${description}" description)
      endif()
      set(skip_entry FALSE)
      if(column STREQUAL "-h,--help")
        set(skip_entry TRUE)
        continue()
      endif()
      if(section STREQUAL "Positionals")
        pw_roff_term(term "${column}" TRUE)
      else()
        pw_roff_term(term "${column}" FALSE)
      endif()
      string(APPEND body ".TP\n${term}\n")
      if(NOT description STREQUAL "")
        pw_roff(text "${description}")
        string(APPEND body "${text}\n")
      endif()
    elseif(line MATCHES "^   +([^ ].*)$" AND NOT skip_entry)
      # A description's next line (or the whole description, below a long option column).
      pw_roff(text "${CMAKE_MATCH_1}")
      string(APPEND body "${text}\n")
    endif()
  endforeach()
  pw_roff(usage "${usage}")
  string(REPLACE "\"" "\\(dq" usage "${usage}")
  string(APPEND roff ".SS \"${usage}\"\n${summary}${body}")
endforeach()

file(READ "${INCLUDE}" hand_written)
file(MAKE_DIRECTORY "${WORK_DIR}")
set(include_file "${WORK_DIR}/patchwork.h2m")
file(WRITE "${include_file}" "${roff}\n${hand_written}")

execute_process(
  COMMAND "${HELP2MAN}" --no-info --section=1 --locale=C.UTF-8
          "--include=${include_file}" "--output=${WORK_DIR}/patchwork.1" "${PATCHWORK}"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "manpage.cmake: help2man failed (${rc}): ${err}")
endif()

# help2man reads CLI11's "-h,--help" (no space after the comma) as one short option: make it
# "\fB\-h\fR, \fB\-\-help\fR" like every other man page.
file(READ "${WORK_DIR}/patchwork.1" page)
string(REGEX REPLACE "\\\\fR,(\\\\-\\\\-[A-Za-z0-9]+(\\\\-[A-Za-z0-9]+)*)" "\\\\fR, \\\\fB\\1\\\\fR" page "${page}")
string(FIND "${page}" "${PATCHWORK}" leaked)
if(NOT leaked EQUAL -1)
  message(FATAL_ERROR "manpage.cmake: the man page names the built binary's path; check the Usage lines")
endif()
file(WRITE "${OUTPUT}.tmp" "${page}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
