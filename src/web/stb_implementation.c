// SPDX-License-Identifier: GPL-3.0-or-later
/* The stb libraries' implementations for the browser build. On Debian they come compiled in
 * libstb (libstb-dev); Emscripten cannot link that, so the same headers are compiled here, with
 * the parts Dear ImGui uses from them (Debian builds ImGui against libstb the same way). */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_RECT_PACK_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <stb/stb_rect_pack.h>
#include <stb/stb_truetype.h>
