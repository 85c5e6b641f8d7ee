#include "scene/regions/font_libraries.h"

#include "capsim/shared_library.h"

namespace capsim {

namespace {

// The sonames of the libraries the build compiled against (CMakeLists.txt),
// so the functions loaded are the ones the headers declare.
const SharedLibrary fontconfig(CAPSIM_FONTCONFIG_SONAME, "text()");
const SharedLibrary freetype(CAPSIM_FREETYPE_SONAME, "text()");
const SharedLibrary harfbuzz(CAPSIM_HARFBUZZ_SONAME, "text()");

}  // namespace

#define CAPSIM_FONT_FUNCTION(library, name) name(library.function<decltype(&::name)>(#name))
FontLibraries::FontLibraries()
    : CAPSIM_FONT_FUNCTION(fontconfig, FcInitLoadConfigAndFonts),
      CAPSIM_FONT_FUNCTION(fontconfig, FcConfigDestroy),
      CAPSIM_FONT_FUNCTION(fontconfig, FcNameParse),
      CAPSIM_FONT_FUNCTION(fontconfig, FcPatternDestroy),
      CAPSIM_FONT_FUNCTION(fontconfig, FcPatternAddBool),
      CAPSIM_FONT_FUNCTION(fontconfig, FcConfigSubstitute),
      CAPSIM_FONT_FUNCTION(fontconfig, FcDefaultSubstitute),
      CAPSIM_FONT_FUNCTION(fontconfig, FcFontMatch),
      CAPSIM_FONT_FUNCTION(fontconfig, FcPatternGetString),
      CAPSIM_FONT_FUNCTION(fontconfig, FcPatternGetInteger),
      CAPSIM_FONT_FUNCTION(freetype, FT_Init_FreeType),
      CAPSIM_FONT_FUNCTION(freetype, FT_Done_FreeType),
      CAPSIM_FONT_FUNCTION(freetype, FT_New_Face),
      CAPSIM_FONT_FUNCTION(freetype, FT_Done_Face),
      CAPSIM_FONT_FUNCTION(freetype, FT_Select_Charmap),
      CAPSIM_FONT_FUNCTION(freetype, FT_Set_Charmap),
      CAPSIM_FONT_FUNCTION(freetype, FT_Set_Char_Size),
      CAPSIM_FONT_FUNCTION(freetype, FT_Load_Glyph),
      CAPSIM_FONT_FUNCTION(freetype, FT_Get_Glyph),
      CAPSIM_FONT_FUNCTION(freetype, FT_Done_Glyph),
      CAPSIM_FONT_FUNCTION(freetype, FT_Glyph_Get_CBox),
      CAPSIM_FONT_FUNCTION(freetype, FT_Outline_Decompose),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_script_from_string),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_script_to_iso15924_tag),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_script_get_horizontal_direction),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_tag_to_string),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_direction_from_string),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_direction_to_string),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_language_from_string),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_unicode_funcs_get_default),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_unicode_script),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_create),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_destroy),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_add_utf8),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_set_direction),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_get_direction),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_set_script),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_set_language),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_get_glyph_infos),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_buffer_get_glyph_positions),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_ft_font_create),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_font_destroy),
      CAPSIM_FONT_FUNCTION(harfbuzz, hb_shape) {}
#undef CAPSIM_FONT_FUNCTION

const FontLibraries& font_libraries() {
  static const FontLibraries table;
  return table;
}

}  // namespace capsim
