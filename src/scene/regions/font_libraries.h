#pragma once
// The functions of FreeType, HarfBuzz and fontconfig that text() calls, from
// the libraries opened on the first text() rather than at every start
// (capsim/shared_library.h): with GLib, Graphite, expat and Brotli, which only
// they bring, they were loaded and relocated on every run.

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_OUTLINE_H
#include <hb-ft.h>
#include <hb.h>

namespace capsim {

struct FontLibraries {
  // Fills the table, opening the libraries; throws std::runtime_error when one
  // cannot be opened, naming it and why.
  FontLibraries();

#define CAPSIM_FONT_FUNCTION(name) decltype(&::name) name
  // fontconfig
  CAPSIM_FONT_FUNCTION(FcInitLoadConfigAndFonts);
  CAPSIM_FONT_FUNCTION(FcConfigDestroy);
  CAPSIM_FONT_FUNCTION(FcNameParse);
  CAPSIM_FONT_FUNCTION(FcPatternDestroy);
  CAPSIM_FONT_FUNCTION(FcPatternAddBool);
  CAPSIM_FONT_FUNCTION(FcConfigSubstitute);
  CAPSIM_FONT_FUNCTION(FcDefaultSubstitute);
  CAPSIM_FONT_FUNCTION(FcFontMatch);
  CAPSIM_FONT_FUNCTION(FcPatternGetString);
  CAPSIM_FONT_FUNCTION(FcPatternGetInteger);
  // FreeType
  CAPSIM_FONT_FUNCTION(FT_Init_FreeType);
  CAPSIM_FONT_FUNCTION(FT_Done_FreeType);
  CAPSIM_FONT_FUNCTION(FT_New_Face);
  CAPSIM_FONT_FUNCTION(FT_Done_Face);
  CAPSIM_FONT_FUNCTION(FT_Select_Charmap);
  CAPSIM_FONT_FUNCTION(FT_Set_Charmap);
  CAPSIM_FONT_FUNCTION(FT_Set_Char_Size);
  CAPSIM_FONT_FUNCTION(FT_Load_Glyph);
  CAPSIM_FONT_FUNCTION(FT_Get_Glyph);
  CAPSIM_FONT_FUNCTION(FT_Done_Glyph);
  CAPSIM_FONT_FUNCTION(FT_Glyph_Get_CBox);
  CAPSIM_FONT_FUNCTION(FT_Outline_Decompose);
  // HarfBuzz
  CAPSIM_FONT_FUNCTION(hb_script_from_string);
  CAPSIM_FONT_FUNCTION(hb_script_to_iso15924_tag);
  CAPSIM_FONT_FUNCTION(hb_script_get_horizontal_direction);
  CAPSIM_FONT_FUNCTION(hb_tag_to_string);
  CAPSIM_FONT_FUNCTION(hb_direction_from_string);
  CAPSIM_FONT_FUNCTION(hb_direction_to_string);
  CAPSIM_FONT_FUNCTION(hb_language_from_string);
  CAPSIM_FONT_FUNCTION(hb_unicode_funcs_get_default);
  CAPSIM_FONT_FUNCTION(hb_unicode_script);
  CAPSIM_FONT_FUNCTION(hb_buffer_create);
  CAPSIM_FONT_FUNCTION(hb_buffer_destroy);
  CAPSIM_FONT_FUNCTION(hb_buffer_add_utf8);
  CAPSIM_FONT_FUNCTION(hb_buffer_set_direction);
  CAPSIM_FONT_FUNCTION(hb_buffer_get_direction);
  CAPSIM_FONT_FUNCTION(hb_buffer_set_script);
  CAPSIM_FONT_FUNCTION(hb_buffer_set_language);
  CAPSIM_FONT_FUNCTION(hb_buffer_get_glyph_infos);
  CAPSIM_FONT_FUNCTION(hb_buffer_get_glyph_positions);
  CAPSIM_FONT_FUNCTION(hb_ft_font_create);
  CAPSIM_FONT_FUNCTION(hb_font_destroy);
  CAPSIM_FONT_FUNCTION(hb_shape);
#undef CAPSIM_FONT_FUNCTION
};

// The table, opened once for the process (from any thread). Libraries that
// cannot be loaded are refused at each call with std::runtime_error.
const FontLibraries& font_libraries();

}  // namespace capsim
