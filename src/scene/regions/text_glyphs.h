#pragma once
// OpenSCAD's text(): the outlines of a string's glyphs, drawn as OpenSCAD
// 2021.01 draws them (its FreetypeRenderer and DrawingCallback), so that a
// text capsim extrudes has OpenSCAD's own vertices:
// - the font is found by fontconfig from OpenSCAD's font name ("Liberation
//   Sans:style=Bold"; empty: "Liberation Sans:style=Regular"), scalable
//   outline fonts only;
// - HarfBuzz shapes the string with the given direction, script and language
//   (an empty direction or script is detected as OpenSCAD detects it);
// - each glyph's outline comes from FreeType at OpenSCAD's scale, with the
//   same load flags, and every curve is cut into text_curve_segments() equal
//   steps of its parameter;
// - halign, valign and spacing place the glyphs as OpenSCAD places them.
// What is left to the caller is OpenSCAD's last step: the union of the
// contours under the non-zero rule (the contours of one glyph wind one way
// for the solid and the other for its holes, as the font draws them).

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsim {

// text()'s parameters, with OpenSCAD's defaults.
struct TextSpec {
  std::string text{};
  double size = 10;
  std::string font{};              // fontconfig name; empty: Liberation Sans
  std::string halign = "left";     // left, center, right
  std::string valign = "baseline"; // baseline, bottom, center, top
  double spacing = 1;
  std::string direction{};         // ltr, rtl, ttb, btt; empty: the script's
  std::string language = "en";
  std::string script{};            // ISO 15924 ("Latn"); empty: detected
  double fn = 0, fa = 12, fs = 2;  // $fn, $fa, $fs
};

// A closed contour, its last vertex joined to its first.
using TextContour = std::vector<glm::dvec2>;

// No font for the name, or a font FreeType cannot read: the message says
// which. (An unknown halign or valign is not an error: OpenSCAD takes it as
// left or baseline, and so does text_contours.)
class TextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// OpenSCAD's number of fragments of a circle of radius r
// (Calc::get_fragments_from_r). More than a million (a zero $fa or $fs, a
// huge $fn) throws TextError.
int openscad_fragments(double r, double fn, double fs, double fa);

// The steps each Bezier curve of a glyph is cut into: an eighth of the
// fragments of a circle of radius size, plus one, at least 2 (OpenSCAD's
// text.cc: "the curved segments of most fonts are relatively short").
int text_curve_segments(const TextSpec& spec);

// The contours of every glyph of spec.text, in text units (size 10: capitals
// about 7 units tall), in glyph order. An empty text gives none.
std::vector<TextContour> text_contours(const TextSpec& spec);

// The path of the font file fontconfig chooses for an OpenSCAD font name.
std::string text_font_file(const std::string& font);

}  // namespace capsim
