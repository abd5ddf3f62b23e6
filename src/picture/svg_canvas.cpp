#include "picture/svg_canvas.hpp"

#include <iomanip>

#include "io/atomic_output.hpp"
#include "io/xml_escape.hpp"

namespace hocav {
namespace {

std::string style_attributes(const ShapeStyle& style) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  out << " fill=\"" << style.fill << "\" stroke=\"" << style.stroke << '"';
  if (style.stroke != "none") out << " stroke-width=\"" << style.stroke_width << "\" stroke-linejoin=\"round\"";
  return out.str();
}

}  // namespace

SvgCanvas::SvgCanvas(double width, double height) : width_(width), height_(height) {
  body_ << std::fixed << std::setprecision(2);
  definitions_ << std::fixed << std::setprecision(2);
}

void SvgCanvas::path(const SvgPath& path, const ShapeStyle& style) {
  if (!path.empty()) body_ << "<path d=\"" << path.data() << '"' << style_attributes(style) << "/>\n";
}

void SvgCanvas::rect(const Rect& box, const ShapeStyle& style) {
  body_ << "<rect x=\"" << box.lower[0] << "\" y=\"" << box.lower[1] << "\" width=\"" << box.width() << "\" height=\"" << box.height()
        << '"' << style_attributes(style) << "/>\n";
}

void SvgCanvas::line(const Vec2& from, const Vec2& to, const ShapeStyle& style) {
  body_ << "<line x1=\"" << from[0] << "\" y1=\"" << from[1] << "\" x2=\"" << to[0] << "\" y2=\"" << to[1] << '"' << style_attributes(style)
        << "/>\n";
}

void SvgCanvas::text(const Vec2& at, std::string_view text, const TextStyle& style) {
  body_ << "<text x=\"" << at[0] << "\" y=\"" << at[1] << "\" font-size=\"" << style.size << "\" text-anchor=\"" << style.anchor
        << "\" fill=\"" << style.fill << '"';
  if (style.bold) body_ << " font-weight=\"bold\"";
  if (style.rotation != 0) body_ << " transform=\"rotate(" << style.rotation << ' ' << at[0] << ' ' << at[1] << ")\"";
  body_ << '>' << xml_escaped(text) << "</text>\n";
}

void SvgCanvas::begin_clip(const Rect& box) {
  ++clips_;
  definitions_ << "<clipPath id=\"clip" << clips_ << "\"><rect x=\"" << box.lower[0] << "\" y=\"" << box.lower[1] << "\" width=\""
               << box.width() << "\" height=\"" << box.height() << "\"/></clipPath>\n";
  body_ << "<g clip-path=\"url(#clip" << clips_ << ")\">\n";
}

void SvgCanvas::end_clip() { body_ << "</g>\n"; }

std::string SvgCanvas::document() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << width_ << "\" height=\"" << height_ << "\" viewBox=\"0 0 "
      << width_ << ' ' << height_ << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  out << "<defs>\n" << definitions_.str() << "</defs>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << body_.str() << "</svg>\n";
  return out.str();
}

void write_svg(const std::string& path, const SvgCanvas& canvas) {
  AtomicOutput out(path);
  out.stream() << canvas.document();
  out.commit();
}

}  // namespace hocav
