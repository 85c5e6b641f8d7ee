#include "scene/regions/text_glyphs.h"

#include "scene/regions/font_libraries.h"
#include "scene/work_limits.h"

#include <fmt/core.h>
#include FT_TRUETYPE_IDS_H

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace capsim {

namespace {

// OpenSCAD's FreetypeRenderer: the character size handed to FreeType (26.6
// units), what an outline coordinate is divided by, and what advances and
// boxes are multiplied by ("1000/1024 ... kept for compatibility").
constexpr double kScale = 1e5;
constexpr double kUnscale = 1.0 / 1.024e5;
// OpenSCAD's GRID_FINE: below this radius a circle has 3 fragments.
constexpr double kGridFine = 0.00000095367431640625;

// FreeType, HarfBuzz and fontconfig, opened on the first text(); libraries
// that cannot be loaded refuse it as any other text() error.
const FontLibraries& fonts() {
  try {
    return font_libraries();
  } catch (const std::runtime_error& e) {
    throw TextError(e.what());
  }
}

// fontconfig's configuration is read once (it scans the font directories);
// a lookup holds the lock, as fontconfig's matching is not documented as
// thread-safe.
std::mutex& fontconfig_mutex() {
  static std::mutex m;
  return m;
}

// Destroyed at exit, so that a leak checker sees fontconfig's memory freed.
FcConfig* fontconfig() {
  static const std::unique_ptr<FcConfig, decltype(&FcConfigDestroy)> config(fonts().FcInitLoadConfigAndFonts(),
                                                                             fonts().FcConfigDestroy);
  return config.get();
}

struct FontFile {
  std::string path;
  int index = 0;
};

// FontCache::find_face_fontconfig: the pattern parsed from the name, limited
// to scalable outline fonts, completed by the configuration's rules.
FontFile find_font(const std::string& name) {
  std::string trimmed = name;
  trimmed.erase(0, trimmed.find_first_not_of(" \t"));
  trimmed.erase(trimmed.find_last_not_of(" \t") + 1);
  const std::string lookup = trimmed.empty() ? "Liberation Sans:style=Regular" : trimmed;
  const std::lock_guard<std::mutex> lock(fontconfig_mutex());
  FcConfig* config = fontconfig();
  if (config == nullptr) throw TextError("fontconfig could not read its configuration");
  const std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)> pattern(
      fonts().FcNameParse(reinterpret_cast<const FcChar8*>(lookup.c_str())), fonts().FcPatternDestroy);
  if (!pattern) throw TextError("font \"" + name + "\": not a fontconfig font name");
  fonts().FcPatternAddBool(pattern.get(), FC_OUTLINE, FcTrue);
  fonts().FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
  fonts().FcConfigSubstitute(config, pattern.get(), FcMatchPattern);
  fonts().FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  const std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)> match(
      fonts().FcFontMatch(config, pattern.get(), &result), fonts().FcPatternDestroy);
  FcChar8* file = nullptr;
  if (!match || fonts().FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch)
    throw TextError("font \"" + lookup + "\": fontconfig finds no scalable font (install fonts-liberation2)");
  FontFile found{reinterpret_cast<const char*>(file), 0};
  fonts().FcPatternGetInteger(match.get(), FC_INDEX, 0, &found.index);
  return found;
}

struct FreeType {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  FreeType() {
    if (fonts().FT_Init_FreeType(&library) != 0) throw TextError("FreeType could not start");
  }
  ~FreeType() {
    if (face != nullptr) fonts().FT_Done_Face(face);
    fonts().FT_Done_FreeType(library);
  }
  FreeType(const FreeType&) = delete;
  FreeType& operator=(const FreeType&) = delete;
};

// FontCache::find_face_fontconfig's choice of character map: Unicode, else
// the first of OpenSCAD's list the font has.
void select_charmap(FT_Face face) {
  if (fonts().FT_Select_Charmap(face, FT_ENCODING_UNICODE) == 0) return;
  const int wanted[][2] = {{TT_PLATFORM_MICROSOFT, TT_MS_ID_UNICODE_CS}, {TT_PLATFORM_ISO, TT_ISO_ID_10646},
                           {TT_PLATFORM_APPLE_UNICODE, -1},         {TT_PLATFORM_MICROSOFT, TT_MS_ID_SYMBOL_CS},
                           {TT_PLATFORM_MACINTOSH, TT_MAC_ID_ROMAN}, {TT_PLATFORM_ISO, TT_ISO_ID_8859_1},
                           {TT_PLATFORM_ISO, TT_ISO_ID_7BIT_ASCII}};
  for (const auto& [platform, encoding] : wanted)
    for (int i = 0; i < face->num_charmaps; ++i) {
      const FT_CharMap map = face->charmaps[i];
      if (map->platform_id == platform && (encoding == -1 || map->encoding_id == encoding) &&
          fonts().FT_Set_Charmap(face, map) == 0)
        return;
    }
}

bool is_ignored_script(hb_script_t script) {
  return script == HB_SCRIPT_COMMON || script == HB_SCRIPT_INHERITED || script == HB_SCRIPT_UNKNOWN ||
         script == HB_SCRIPT_INVALID;
}

// FreetypeRenderer::detect_properties: the one script of the text's
// characters (unknown when they mix scripts), and the script's direction.
void detect_properties(TextSpec& spec) {
  hb_script_t script = fonts().hb_script_from_string(spec.script.c_str(), -1);
  if (script == HB_SCRIPT_INVALID) {
    hb_buffer_t* buffer = fonts().hb_buffer_create();
    fonts().hb_buffer_add_utf8(buffer, spec.text.c_str(), static_cast<int>(spec.text.size()), 0,
                       static_cast<int>(spec.text.size()));
    unsigned count = 0;
    const hb_glyph_info_t* info = fonts().hb_buffer_get_glyph_infos(buffer, &count);
    for (unsigned i = 0; i < count; ++i) {
      const hb_script_t s = fonts().hb_unicode_script(fonts().hb_unicode_funcs_get_default(), info[i].codepoint);
      if (is_ignored_script(s)) continue;
      if (script == HB_SCRIPT_INVALID)
        script = s;
      else if (script != s && script != HB_SCRIPT_UNKNOWN)
        script = HB_SCRIPT_UNKNOWN;
    }
    fonts().hb_buffer_destroy(buffer);
    if (!is_ignored_script(script)) {
      char tag[5] = {0, 0, 0, 0, 0};
      fonts().hb_tag_to_string(fonts().hb_script_to_iso15924_tag(script), tag);
      spec.script = tag;
    }
  }
  if (fonts().hb_direction_from_string(spec.direction.c_str(), -1) == HB_DIRECTION_INVALID)
    spec.direction = fonts().hb_direction_to_string(fonts().hb_script_get_horizontal_direction(script));
}

// DrawingCallback: the contours of the glyph being drawn, each vertex placed
// at size * (point + glyph offset + advance so far).
struct Drawing {
  double size;
  int segments;
  glm::dvec2 offset{0}, advance{0}, pen{0};
  TextContour contour;
  std::vector<TextContour>* out;

  void add_vertex(const glm::dvec2& v) { contour.push_back(size * (v + offset + advance)); }
  void close_contour() {
    if (!contour.empty()) out->push_back(std::move(contour));
    contour.clear();
  }
  static glm::dvec2 point(const FT_Vector* v) { return {v->x / kScale, v->y / kScale}; }
  static Drawing& of(void* user) { return *static_cast<Drawing*>(user); }

  static int move_to(const FT_Vector* to, void* user) {
    Drawing& d = of(user);
    d.close_contour();
    d.pen = point(to);
    d.add_vertex(d.pen);
    return 0;
  }
  static int line_to(const FT_Vector* to, void* user) {
    Drawing& d = of(user);
    d.pen = point(to);
    d.add_vertex(d.pen);
    return 0;
  }
  // The expressions are OpenSCAD's own, term by term, so that each vertex is
  // the same double.
  static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    Drawing& d = of(user);
    const glm::dvec2 c1 = point(control), end = point(to);
    for (int i = 1; i <= d.segments; ++i) {
      const double a = i * (1.0 / static_cast<double>(d.segments));
      d.add_vertex(d.pen * std::pow(1 - a, 2) + c1 * 2.0 * std::pow(1 - a, 1) * a + end * std::pow(a, 2));
    }
    d.pen = end;
    return 0;
  }
  static int cubic_to(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
    Drawing& d = of(user);
    const glm::dvec2 c1 = point(control1), c2 = point(control2), end = point(to);
    for (int i = 1; i <= d.segments; ++i) {
      const double a = i * (1.0 / static_cast<double>(d.segments));
      d.add_vertex(d.pen * std::pow(1 - a, 3) + c1 * 3.0 * std::pow(1 - a, 2) * a +
                   c2 * 3.0 * std::pow(1 - a, 1) * std::pow(a, 2) + end * std::pow(a, 3));
    }
    d.pen = end;
    return 0;
  }
};

struct Glyph {
  FT_Glyph glyph = nullptr;
  hb_glyph_position_t position{};
};

double x_offset(const std::string& halign, double width) {
  if (halign == "right") return -width;
  if (halign == "center") return -width / 2.0;
  return 0;
}

double y_offset(const std::string& valign, double ascend, double descend) {
  if (valign == "top") return -ascend;
  if (valign == "center") return descend / 2.0 - ascend / 2.0;
  if (valign == "bottom") return descend;
  return 0;
}

}  // namespace

int openscad_fragments(double r, double fn, double fs, double fa) {
  if (r < kGridFine || std::isinf(fn) || std::isnan(fn)) return 3;
  const double fragments =
      fn > 0.0 ? (fn >= 3 ? std::trunc(fn) : 3)
               : std::ceil(std::fmax(std::fmin(360.0 / fa, r * 2 * std::numbers::pi / fs), 5));
  // OpenSCAD would convert any number here; beyond this it is not a number
  // of fragments anyone means ($fa or $fs 0, or a huge $fn).
  if (!(fragments <= kMaxFragments))
    throw TextError(fmt::format("$fn = {}, $fa = {}, $fs = {} give more than {} fragments", fn, fa, fs,
                                kMaxFragments));
  return static_cast<int>(fragments);
}

int text_curve_segments(const TextSpec& spec) {
  const int fragments = openscad_fragments(spec.size, spec.fn, spec.fs, spec.fa);
  return static_cast<int>(std::max(std::floor(fragments / 8) + 1, 2.0));
}

std::string text_font_file(const std::string& font) { return find_font(font).path; }

// The glyphs FreeType gave, freed however text_contours ends.
struct GlyphList {
  std::vector<Glyph> glyphs;
  GlyphList() = default;
  GlyphList(const GlyphList&) = delete;
  GlyphList& operator=(const GlyphList&) = delete;
  ~GlyphList() {
    for (const Glyph& g : glyphs) fonts().FT_Done_Glyph(g.glyph);
  }
};

std::vector<TextContour> text_contours(const TextSpec& given) {
  TextSpec spec = given;
  const int segments = text_curve_segments(spec);  // throws before anything is allocated
  detect_properties(spec);
  const FontFile file = find_font(spec.font);
  FreeType ft;
  if (fonts().FT_New_Face(ft.library, file.path.c_str(), file.index, &ft.face) != 0)
    throw TextError("font file " + file.path + ": FreeType cannot read it");
  select_charmap(ft.face);
  if (fonts().FT_Set_Char_Size(ft.face, 0, static_cast<FT_F26Dot6>(kScale), 100, 100) != 0)
    throw TextError("font file " + file.path + ": FreeType cannot size it");

  hb_font_t* font = fonts().hb_ft_font_create(ft.face, nullptr);
  hb_buffer_t* buffer = fonts().hb_buffer_create();
  fonts().hb_buffer_set_direction(buffer, fonts().hb_direction_from_string(spec.direction.c_str(), -1));
  fonts().hb_buffer_set_script(buffer, fonts().hb_script_from_string(spec.script.c_str(), -1));
  fonts().hb_buffer_set_language(buffer, fonts().hb_language_from_string(spec.language.c_str(), -1));
  fonts().hb_buffer_add_utf8(buffer, spec.text.c_str(), static_cast<int>(spec.text.size()), 0,
                     static_cast<int>(spec.text.size()));
  fonts().hb_shape(font, buffer, nullptr, 0);
  unsigned count = 0;
  const hb_glyph_info_t* info = fonts().hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* positions = fonts().hb_buffer_get_glyph_positions(buffer, &count);
  const bool horizontal = HB_DIRECTION_IS_HORIZONTAL(fonts().hb_buffer_get_direction(buffer));

  // A glyph FreeType cannot load is left out, as OpenSCAD leaves it out.
  GlyphList list;
  std::vector<Glyph>& glyphs = list.glyphs;
  glyphs.reserve(count);  // so that no push_back throws and loses a glyph
  for (unsigned i = 0; i < count; ++i) {
    Glyph g;
    if (fonts().FT_Load_Glyph(ft.face, info[i].codepoint, FT_LOAD_DEFAULT) != 0) continue;
    if (fonts().FT_Get_Glyph(ft.face->glyph, &g.glyph) != 0) continue;
    g.position = positions[i];
    glyphs.push_back(g);
  }
  fonts().hb_buffer_destroy(buffer);
  fonts().hb_font_destroy(font);

  double width = 0, ascend = 0, descend = 0;
  for (const Glyph& g : glyphs) {
    FT_BBox box;
    fonts().FT_Glyph_Get_CBox(g.glyph, FT_GLYPH_BBOX_GRIDFIT, &box);
    if (horizontal) {
      width += g.position.x_advance * kUnscale * spec.spacing;
      ascend = std::max(ascend, std::max(0.0, box.yMax * kUnscale));
      descend = std::max(descend, std::max(0.0, -box.yMin * kUnscale));
    } else {
      width = std::max(width, (box.xMax - box.xMin) * kUnscale);
      ascend += g.position.y_advance * kUnscale * spec.spacing;
    }
  }
  const double dx = x_offset(spec.halign, width), dy = y_offset(spec.valign, ascend, descend);

  std::vector<TextContour> contours;
  Drawing drawing{spec.size, segments, {}, {}, {}, {}, &contours};
  FT_Outline_Funcs funcs{};
  funcs.move_to = &Drawing::move_to;
  funcs.line_to = &Drawing::line_to;
  funcs.conic_to = &Drawing::conic_to;
  funcs.cubic_to = &Drawing::cubic_to;
  for (const Glyph& g : glyphs) {
    drawing.offset = {dx + g.position.x_offset * kUnscale, dy + g.position.y_offset * kUnscale};
    if (g.glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
      FT_Outline outline = reinterpret_cast<FT_OutlineGlyph>(g.glyph)->outline;
      fonts().FT_Outline_Decompose(&outline, &funcs, &drawing);
    }
    drawing.advance += glm::dvec2(g.position.x_advance * kUnscale * spec.spacing,
                                  g.position.y_advance * kUnscale * spec.spacing);
    drawing.close_contour();
  }
  return contours;
}

}  // namespace capsim
