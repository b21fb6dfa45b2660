#include "cli/SvgDocument.h"

#include <cctype>
#include <cmath>

namespace ivshadow {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Two decimals: a hundredth of a pixel is finer than any display shows.
std::string number(double value) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << value;
  std::string text = out.str();
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

std::string rgb(const SvgColour& colour) {
  return "rgb(" + std::to_string(colour.r) + "," + std::to_string(colour.g) + "," +
         std::to_string(colour.b) + ")";
}

std::string points(const std::vector<SvgPoint>& points) {
  std::string out;
  for (const SvgPoint& p : points)
    out += (out.empty() ? "" : " ") + number(p.x) + "," + number(p.y);
  return out;
}

}  // namespace

SvgColour SvgColour::darker(double factor) const {
  const auto channel = [factor](int c) { return int(std::lround(c / factor)); };
  return {channel(r), channel(g), channel(b), opacity};
}

double SvgFont::width(const std::string& text) const {
  double ems = 0.0;
  for (const char c : text) {
    // A byte that continues a UTF-8 sequence adds no character of its own.
    if ((static_cast<unsigned char>(c) & 0xC0) == 0x80) continue;
    ems += std::isdigit(static_cast<unsigned char>(c)) ? 0.64 : 0.6;
  }
  return ems * size * (bold ? 1.1 : 1.0);
}

SvgDocument::SvgDocument(int width, int height) : width_(width), height_(height) {}

void SvgDocument::style(const SvgStyle& style) {
  if (style.fill == nullptr) {
    body_ << " fill=\"none\"";
  } else {
    body_ << " fill=\"" << rgb(*style.fill) << '"';
    if (style.fill->opacity < 1.0)
      body_ << " fill-opacity=\"" << number(style.fill->opacity) << '"';
  }
  if (style.stroke != nullptr) {
    body_ << " stroke=\"" << rgb(*style.stroke) << "\" stroke-width=\"" << number(style.strokeWidth)
          << '"';
    if (style.stroke->opacity < 1.0)
      body_ << " stroke-opacity=\"" << number(style.stroke->opacity) << '"';
  }
}

void SvgDocument::rect(double x, double y, double w, double h, const SvgStyle& s) {
  body_ << "<rect x=\"" << number(x) << "\" y=\"" << number(y) << "\" width=\"" << number(w)
        << "\" height=\"" << number(h) << '"';
  style(s);
  body_ << "/>\n";
}

void SvgDocument::line(SvgPoint from, SvgPoint to, const SvgColour& colour, double width) {
  polyline({from, to}, colour, width);
}

void SvgDocument::circle(SvgPoint centre, double radius, const SvgStyle& s) {
  body_ << "<circle cx=\"" << number(centre.x) << "\" cy=\"" << number(centre.y) << "\" r=\""
        << number(radius) << '"';
  style(s);
  body_ << "/>\n";
}

void SvgDocument::polygon(const std::vector<SvgPoint>& corners, const SvgStyle& s) {
  body_ << "<polygon points=\"" << points(corners) << '"';
  style(s);
  body_ << "/>\n";
}

void SvgDocument::polyline(const std::vector<SvgPoint>& line, const SvgColour& colour,
                           double width) {
  body_ << "<polyline points=\"" << points(line) << '"';
  style({nullptr, &colour, width});
  body_ << "/>\n";
}

void SvgDocument::text(SvgPoint at, const std::string& text, const SvgFont& font, SvgAnchor anchor,
                       const SvgColour& colour, double degrees) {
  static const char* const kAnchors[] = {"start", "middle", "end"};
  body_ << "<text x=\"" << number(at.x) << "\" y=\"" << number(at.y) << "\" font-size=\""
        << number(font.size) << "\" text-anchor=\"" << kAnchors[int(anchor)]
        << "\" dominant-baseline=\"central\" fill=\"" << rgb(colour) << '"';
  if (font.bold) body_ << " font-weight=\"bold\"";
  if (degrees != 0.0)
    body_ << " transform=\"rotate(" << number(degrees) << " " << number(at.x) << " " << number(at.y)
          << ")\"";
  body_ << '>' << escaped(text) << "</text>\n";
}

std::string SvgDocument::str() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
         std::to_string(width_) + "\" height=\"" + std::to_string(height_) + "\" viewBox=\"0 0 " +
         std::to_string(width_) + " " + std::to_string(height_) +
         "\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n" + body_.str() + "</svg>\n";
}

}  // namespace ivshadow
