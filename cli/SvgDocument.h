#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace ivshadow {

// An RGB colour with its opacity, as SVG's fill and stroke take it.
struct SvgColour {
  int r = 0, g = 0, b = 0;
  double opacity = 1.0;
  // The colour with each channel divided by `factor` (Qt's darker(130) is factor 1.3).
  SvgColour darker(double factor) const;
};

struct SvgPoint {
  double x = 0.0, y = 0.0;
};

// How a shape is drawn: no fill and no stroke unless given.
struct SvgStyle {
  const SvgColour* fill = nullptr;
  const SvgColour* stroke = nullptr;
  double strokeWidth = 1.0;
};

enum class SvgAnchor { Start, Middle, End };

struct SvgFont {
  double size = 12.0;  // px
  bool bold = false;
  // About how wide `text` is: SVG leaves the font's metrics to the viewer, so a layout that
  // keeps labels apart reckons with DejaVu Sans' mean advance (about 0.6 em; digits 0.64).
  double width(const std::string& text) const;
};

// Writes an SVG picture of fixed size in user units (px): shapes and text in the order drawn,
// later ones over earlier ones, as a painter would. Text is escaped for XML; the font family
// is the one the chart was laid out with, then any sans-serif.
class SvgDocument {
 public:
  SvgDocument(int width, int height);

  void rect(double x, double y, double w, double h, const SvgStyle& style);
  void line(SvgPoint from, SvgPoint to, const SvgColour& colour, double width);
  void circle(SvgPoint centre, double radius, const SvgStyle& style);
  void polygon(const std::vector<SvgPoint>& corners, const SvgStyle& style);
  void polyline(const std::vector<SvgPoint>& points, const SvgColour& colour, double width);
  // Text whose baseline's middle (vertically: the middle of its x-height band) is at `at`,
  // anchored at its start, middle or end; rotated by `degrees` about `at`.
  void text(SvgPoint at, const std::string& text, const SvgFont& font, SvgAnchor anchor,
            const SvgColour& colour, double degrees = 0.0);

  std::string str() const;

 private:
  void style(const SvgStyle& style);

  int width_, height_;
  std::ostringstream body_;
};

}  // namespace ivshadow
