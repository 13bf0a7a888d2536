# Which tests of a suite start a JACK server of their own (tests/support/jack_server.hpp), read from
# their sources, so that every such test takes the one jack_server lock without a list kept by hand:
# jack2 keeps one registry for the machine, and a server killed and started again under one test
# made another test's client fail to open its own server (CI, two panel tests at once).
#
# nibrig_jack_tests(<out> <source>...) sets <out> to an alternation of "Suite[.]Test" regexes for each
# TEST, TEST_F, TEST_P or TYPED_TEST whose body names JackServer, or every test of a file whose code
# before its first test does (a fixture or helper that starts one).
function(nibrig_jack_tests out)
  set(found "")
  foreach(source IN LISTS ARGN)
    file(READ "${source}" text)
    string(FIND "${text}" "JackServer" at)
    if(at EQUAL -1)
      continue()
    endif()
    # Characters that CMake's lists treat specially are taken out before the text is cut into tests.
    string(REGEX REPLACE "[][;\\\\]" " " text "${text}")
    string(REGEX REPLACE "\n((TYPED_)?TEST(_F|_P)?\\()" "\n;\\1" chunks "${text}")
    list(POP_FRONT chunks preamble)
    string(FIND "${preamble}" "JackServer" in_preamble)
    foreach(chunk IN LISTS chunks)
      string(FIND "${chunk}" "JackServer" in_test)
      if(in_preamble EQUAL -1 AND in_test EQUAL -1)
        continue()
      endif()
      if(chunk MATCHES "^(TYPED_)?TEST(_F|_P)?\\([ \n]*([A-Za-z0-9_]+)[ \n]*,[ \n]*([A-Za-z0-9_]+)")
        list(APPEND found "${CMAKE_MATCH_3}[.]${CMAKE_MATCH_4}")
      endif()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES found)
  list(JOIN found "|" alternation)
  set(${out} "${alternation}" PARENT_SCOPE)
endfunction()
