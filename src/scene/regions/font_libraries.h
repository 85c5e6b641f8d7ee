#pragma once
// The functions of FreeType, HarfBuzz and fontconfig that text() calls, from
// the libraries opened on the first text() rather than at every start
// (capsim/system/shared_library.h): with GLib, Graphite, expat and Brotli, which only
// they bring, they were loaded and relocated on every run.

#include "capsim/system/shared_library.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_OUTLINE_H
#include <hb-ft.h>
#include <hb.h>

namespace capsim {

// The libraries, of the sonames the build compiled against (CMakeLists.txt),
// so the functions loaded are the ones the headers declare.
const SharedLibrary& fontconfig_library();
const SharedLibrary& freetype_library();
const SharedLibrary& harfbuzz_library();

// Making the table opens the libraries; it throws std::runtime_error when one
// cannot be opened, naming it and why.
struct FontLibraries {
#define CAPSIM_FONT_FUNCTION(library, name) decltype(&::name) name = library().function<decltype(&::name)>(#name)
  // fontconfig
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcInitLoadConfigAndFonts);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcConfigDestroy);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcNameParse);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcPatternDestroy);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcPatternAddBool);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcConfigSubstitute);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcDefaultSubstitute);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcFontMatch);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcPatternGetString);
  CAPSIM_FONT_FUNCTION(fontconfig_library, FcPatternGetInteger);
  // FreeType
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Init_FreeType);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Done_FreeType);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_New_Face);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Done_Face);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Select_Charmap);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Set_Charmap);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Set_Char_Size);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Load_Glyph);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Get_Glyph);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Done_Glyph);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Glyph_Get_CBox);
  CAPSIM_FONT_FUNCTION(freetype_library, FT_Outline_Decompose);
  // HarfBuzz
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_script_from_string);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_script_to_iso15924_tag);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_script_get_horizontal_direction);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_tag_to_string);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_direction_from_string);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_direction_to_string);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_language_from_string);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_unicode_funcs_get_default);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_unicode_script);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_create);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_destroy);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_add_utf8);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_set_direction);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_get_direction);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_set_script);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_set_language);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_get_glyph_infos);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_buffer_get_glyph_positions);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_ft_font_create);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_font_destroy);
  CAPSIM_FONT_FUNCTION(harfbuzz_library, hb_shape);
#undef CAPSIM_FONT_FUNCTION
};

// The table, opened once for the process (from any thread). Libraries that
// cannot be loaded are refused at each call with std::runtime_error.
const FontLibraries& font_libraries();

}  // namespace capsim
