# SPDX-License-Identifier: GPL-3.0-or-later
# The viewer in the browser: sculpt-view.js and sculpt-view.wasm, started by web/index.html with
# the page's address as its command line (web/sculpt-page.js). Its reconstructions run in a Web
# Worker on the core's module (web/CMakeLists.txt), so it links no reconstruction code itself.
set_target_properties(sculpt-view PROPERTIES SUFFIX ".js")
target_link_options(sculpt-view PRIVATE
  -sENVIRONMENT=web
  -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=4GB
  -sEXPORTED_FUNCTIONS=_main,_malloc,_free
  -sEXPORTED_RUNTIME_METHODS=FS,UTF8ToString,allocateUTF8)
