# Files compiled into the binary as "builtin:<name>" (io/builtin_files.h): an assembler
# .incbin per file in one generated source, which compiles in no time whatever the file size
# (no hex arrays). Each entry is NAME=PATH, PATH relative to the source folder; the name's
# extension tells OpenImageIO the format.
set(PHELLEM_BUILTIN_FILES
  rooitou_park_1k.hdr=data/hdri/rooitou_park_1k.hdr
  bark_brown_01.jpg=data/photos/bark_brown_01_polyhaven.jpg
  bark_brown_01_disp.jpg=data/photos/bark_brown_01_polyhaven_disp.jpg)

set(_asm "")
set(_decl "")
set(_table "")
set(_deps "")
set(_i 0)
foreach(_entry IN LISTS PHELLEM_BUILTIN_FILES)
  string(REPLACE "=" ";" _pair "${_entry}")
  list(GET _pair 0 _name)
  list(GET _pair 1 _rel)
  set(_file "${CMAKE_SOURCE_DIR}/${_rel}")
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "builtin file ${_name}: ${_file} does not exist")
  endif()
  list(APPEND _deps "${_file}")
  # The content hash in the source: a changed file changes the source (ccache sees no .incbin).
  file(SHA256 "${_file}" _sha)
  string(APPEND _asm "    \"# ${_name} sha256 ${_sha}\\n\"\n")
  string(APPEND _asm "    \".balign 16\\n phellem_builtin_${_i}_begin:\\n .incbin \\\"${_file}\\\"\\n phellem_builtin_${_i}_end:\\n\"\n")
  string(APPEND _decl "extern \"C\" const unsigned char phellem_builtin_${_i}_begin[], phellem_builtin_${_i}_end[];\n")
  string(APPEND _table "    {\"${_name}\", phellem_builtin_${_i}_begin, phellem_builtin_${_i}_end},\n")
  math(EXPR _i "${_i} + 1")
endforeach()
set(PHELLEM_BUILTIN_ASM "${_asm}")
set(PHELLEM_BUILTIN_DECL "${_decl}")
set(PHELLEM_BUILTIN_TABLE "${_table}")
configure_file(${CMAKE_SOURCE_DIR}/cmake/builtin_files.cpp.in ${CMAKE_BINARY_DIR}/generated/builtin_files.cpp @ONLY)
# The object depends on the files it includes (the compiler does not see them); a changed
# file re-runs CMake, which writes its new hash into the source.
set(PHELLEM_BUILTIN_FILE_PATHS "${_deps}")
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_deps})
