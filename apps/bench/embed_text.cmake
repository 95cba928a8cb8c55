# cmake -DIN=file -DOUT=file.cpp -DNAME=symbol -DNAMESPACE=ns -P embed_text.cmake
# Writes a C++ source defining `const char* NAMESPACE::NAME()` returning the text of IN, so that
# a script ships inside the binary. ISO C++ only promises string literals of 65536 characters
# (-Woverlength-strings under -Wpedantic), hence the check.
file(READ "${IN}" text)
string(LENGTH "${text}" length)
if(length GREATER 65000)
  message(FATAL_ERROR "${IN} is ${length} characters: split it, C++ string literals stop at 65536")
endif()
string(FIND "${text}" ")navfuse_embed\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )navfuse_embed\"")
endif()
file(WRITE "${OUT}.tmp" "// Generated from ${IN} by embed_text.cmake: do not edit.\n"
  "namespace ${NAMESPACE} {\nconst char* ${NAME}() {\n  return R\"navfuse_embed(${text})navfuse_embed\";\n}\n}\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
