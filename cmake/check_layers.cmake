# Fails when a file includes a folder outside the set its own folder may include, or when a
# folder below renderer/ includes Embree. Run as the `include_graph` test:
#   cmake -DSOURCE_DIR=<repo> -P cmake/check_layers.cmake
#
# The graph (each folder may include itself and the folders listed; see docs/architecture.md):
#   util      -> util
#   bark      -> util bark
#   io        -> util bark io
#   scene     -> util bark io scene
#   compare   -> util bark io scene compare       (not renderer: compare renders nothing)
#   renderer  -> util bark io scene renderer      (not compare)
#   preview   -> util bark io scene preview       (OpenGL; not renderer: no Embree)
#   lookdev   -> util bark io scene compare renderer lookdev   (light rigs: renders for comparisons)
#   cli       -> everything
set(folders util bark io scene compare renderer preview lookdev cli)
set(allowed_util util)
set(allowed_bark util bark)
set(allowed_io util bark io)
set(allowed_scene util bark io scene)
set(allowed_compare util bark io scene compare)
set(allowed_renderer util bark io scene renderer)
set(allowed_preview util bark io scene preview)
set(allowed_lookdev util bark io scene compare renderer lookdev)
set(allowed_cli ${folders})
# Embree is the path tracer's alone: these folders build and link without it.
set(embree_banned util bark io scene compare preview)

set(violations "")
foreach(from IN LISTS folders)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${from}/*.h" "${SOURCE_DIR}/${from}/*.cpp")
  foreach(f IN LISTS files)
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${f}")
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([a-z_]+)/.*" "\\1" to "${line}")
      list(FIND folders "${to}" known)
      list(FIND allowed_${from} "${to}" ok)
      if(known GREATER -1 AND ok EQUAL -1)
        list(JOIN allowed_${from} ", " may)
        string(APPEND violations "  ${rel} includes ${to}/ (${from}/ may include only: ${may})\n")
      endif()
    endforeach()
    list(FIND embree_banned "${from}" banned)
    if(banned GREATER -1)
      file(STRINGS "${f}" embree REGEX "^[ \t]*#[ \t]*include[ \t]+<embree")
      if(embree)
        string(APPEND violations "  ${rel} includes Embree (only renderer/ and cli/ may)\n")
      endif()
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "include graph broken (cmake/check_layers.cmake lists what each folder may include):\n${violations}")
endif()
message(STATUS "include graph: every folder includes only its allowed set; no Embree below renderer/")
