# SPDX-License-Identifier: GPL-3.0-or-later
# The browser build's libraries (configured by emcmake; scripts/web). Emscripten brings its own C
# and C++ libraries and does not search the host's /usr/include, so the header-only libraries
# Debian installs (CGAL, Boost, fmt, nlohmann-json, CLI11, GLM, stb) are reached through a folder
# of links to them alone; what Debian ships compiled (libstb, Dear ImGui, libwebp, giflib) is compiled
# from Debian's own sources: scripts/web fetches the source packages into SCULPT_DEBIAN_SOURCES.
# The targets made here carry the names the native build finds, so the rest of the build is one.

# stb, libwebp and giflib are C.
enable_language(C)

set(SCULPT_DEBIAN_SOURCES "${CMAKE_BINARY_DIR}/debian-sources" CACHE PATH
    "Where `apt-get source imgui libwebp giflib` unpacked Dear ImGui, libwebp and giflib")

# C++ exceptions as WebAssembly's own (CGAL's filtered predicates throw on every filter failure;
# JavaScript-based exceptions make each call that may throw a trip through JavaScript).
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
# WebAssembly rounds to nearest and cannot change it: CGAL's interval arithmetic widens its
# bounds instead of switching the rounding mode. No GMP: CGAL's exact fallback uses Boost's.
add_compile_definitions(CGAL_DISABLE_GMP CGAL_ALWAYS_ROUND_TO_NEAREST BOOST_ALL_NO_LIB)

set(SCULPT_HOST_INCLUDE ${CMAKE_BINARY_DIR}/host-include)
file(MAKE_DIRECTORY ${SCULPT_HOST_INCLUDE})
foreach(folder CGAL boost fmt nlohmann CLI glm stb)
  if(NOT EXISTS /usr/include/${folder})
    message(FATAL_ERROR "/usr/include/${folder} is missing: run scripts/install-dependencies")
  endif()
  file(CREATE_LINK /usr/include/${folder} ${SCULPT_HOST_INCLUDE}/${folder} SYMBOLIC)
endforeach()

# Eigen, for CGAL's jet smoothing (the cleaning stage), as CGAL's Eigen3 support target names it.
if(NOT EXISTS /usr/include/eigen3/Eigen)
  message(FATAL_ERROR "/usr/include/eigen3 is missing: run scripts/install-dependencies")
endif()
file(CREATE_LINK /usr/include/eigen3/Eigen ${SCULPT_HOST_INCLUDE}/Eigen SYMBOLIC)

function(sculpt_header_library target)
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
                                             ${SCULPT_HOST_INCLUDE}
                                             INTERFACE_INCLUDE_DIRECTORIES ${SCULPT_HOST_INCLUDE})
endfunction()
foreach(target CGAL::CGAL CLI11::CLI11 nlohmann_json::nlohmann_json glm::glm fmt::fmt)
  sculpt_header_library(${target})
endforeach()
set_target_properties(fmt::fmt PROPERTIES INTERFACE_COMPILE_DEFINITIONS FMT_HEADER_ONLY)
sculpt_header_library(CGAL::Eigen3_support)
set_target_properties(CGAL::Eigen3_support PROPERTIES INTERFACE_COMPILE_DEFINITIONS CGAL_EIGEN3_ENABLED)

# stb, as libstb is built.
add_library(sculpt_stb STATIC src/web/stb_implementation.c)
target_include_directories(sculpt_stb SYSTEM PUBLIC ${SCULPT_HOST_INCLUDE})
add_library(PkgConfig::STB ALIAS sculpt_stb)

# Dear ImGui 1.86 with its GLFW and OpenGL 3 backends, built as Debian builds it (against stb).
set(imgui ${SCULPT_DEBIAN_SOURCES}/imgui-1.86)
if(NOT EXISTS ${imgui}/imgui.cpp)
  message(FATAL_ERROR "${imgui} is missing: scripts/web fetches Debian's source package imgui")
endif()
add_library(sculpt_imgui STATIC ${imgui}/imgui.cpp ${imgui}/imgui_draw.cpp ${imgui}/imgui_tables.cpp
                                ${imgui}/imgui_widgets.cpp ${imgui}/backends/imgui_impl_glfw.cpp
                                ${imgui}/backends/imgui_impl_opengl3.cpp)
target_include_directories(sculpt_imgui SYSTEM PUBLIC ${imgui} ${imgui}/backends)
target_compile_definitions(sculpt_imgui PUBLIC
  IMGUI_DISABLE_STB_RECT_PACK_IMPLEMENTATION "IMGUI_STB_RECT_PACK_FILENAME=<stb/stb_rect_pack.h>"
  IMGUI_DISABLE_STB_TRUETYPE_IMPLEMENTATION "IMGUI_STB_TRUETYPE_FILENAME=<stb/stb_truetype.h>")
target_link_libraries(sculpt_imgui PUBLIC sculpt_stb)
target_link_options(sculpt_imgui PUBLIC -sUSE_GLFW=3)
target_compile_options(sculpt_imgui PRIVATE -sUSE_GLFW=3)
add_library(PkgConfig::IMGUI ALIAS sculpt_imgui)

# libwebp 1.2.4 (with Debian's security patches), for animated WebP exports.
set(webp ${SCULPT_DEBIAN_SOURCES}/libwebp-1.2.4)
if(NOT EXISTS ${webp}/src/webp/encode.h)
  message(FATAL_ERROR "${webp} is missing: scripts/web fetches Debian's source package libwebp")
endif()
file(GLOB webp_sources ${webp}/src/dec/*.c ${webp}/src/dsp/*.c ${webp}/src/enc/*.c
                       ${webp}/src/mux/*.c ${webp}/src/utils/*.c ${webp}/sharpyuv/*.c)
add_library(sculpt_webp STATIC ${webp_sources})
target_include_directories(sculpt_webp SYSTEM PUBLIC ${webp}/src PRIVATE ${webp})
add_library(PkgConfig::WEBP ALIAS sculpt_webp)

# giflib 5.2.1 (with Debian's patches), for animated GIF exports: the encoder and its colour
# quantizer.
set(gif ${SCULPT_DEBIAN_SOURCES}/giflib-5.2.1)
if(NOT EXISTS ${gif}/gif_lib.h)
  message(FATAL_ERROR "${gif} is missing: scripts/web fetches Debian's source package giflib")
endif()
add_library(sculpt_gif STATIC ${gif}/egif_lib.c ${gif}/gif_err.c ${gif}/gif_hash.c ${gif}/gifalloc.c
                              ${gif}/openbsd-reallocarray.c ${gif}/quantize.c)
target_include_directories(sculpt_gif SYSTEM PUBLIC ${gif})
add_library(GIF::GIF ALIAS sculpt_gif)

# The window: Emscripten's GLFW on the page's canvas, WebGL 2 (OpenGL ES 3.0).
add_library(sculpt_browser_window INTERFACE)
target_link_options(sculpt_browser_window INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2
                                                    -sMAX_WEBGL_VERSION=2)
add_library(glfw ALIAS sculpt_browser_window)
