#include "studies/svg_plot.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::studies {

void begin_document(std::ostream& s, double width, double height, const std::string& title) {
  s << "<?xml version='1.0' encoding='UTF-8'?>\n"
    << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
    << "' font-family='sans-serif' font-size='12'>\n"
    << "<rect width='" << width << "' height='" << height << "' fill='white'/>\n"
    << "<text x='" << width / 2 << "' y='20' text-anchor='middle' font-size='15'>" << escape(title) << "</text>\n";
}

void end_document(std::ostream& s) { s << "</svg>\n"; }

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

LogLogPanel::LogLogPanel(double x0, double y0, const std::vector<double>& xs, const std::vector<double>& ys,
                         double x_floor, double y_floor)
    : x0_(x0), y0_(y0), x_floor_(x_floor), y_floor_(y_floor) {
  auto decades = [](const std::vector<double>& values, double floor, double& d0, double& d1) {
    double lo = 1e300, hi = 0;
    for (double v : values) {
      lo = std::min(lo, std::max(v, floor));
      hi = std::max(hi, std::max(v, floor));
    }
    if (values.empty()) lo = hi = 1.0;
    d0 = std::floor(std::log10(lo));
    d1 = std::ceil(std::log10(hi) + 1e-9);
  };
  decades(xs, x_floor, x_decade0_, x_decade1_);
  decades(ys, y_floor, y_decade0_, y_decade1_);
}

double LogLogPanel::x(double value) const {
  const double plot_width = width - left - right;
  return x0_ + left +
         plot_width * (std::log10(std::max(value, x_floor_)) - x_decade0_) / std::max(1.0, x_decade1_ - x_decade0_);
}

double LogLogPanel::y(double value) const {
  const double plot_height = height - top - bottom;
  return y0_ + top +
         plot_height *
             (1.0 - (std::log10(std::max(value, y_floor_)) - y_decade0_) / std::max(1.0, y_decade1_ - y_decade0_));
}

void LogLogPanel::draw_axes(std::ostream& s, const std::string& x_label, const std::string& y_label) const {
  const double pw = width - left - right, ph = height - top - bottom;
  s << "<rect x='" << x0_ + left << "' y='" << y0_ + top << "' width='" << pw << "' height='" << ph
    << "' fill='none' stroke='#444'/>\n";
  for (double d = x_decade0_; d <= x_decade1_ + 1e-9; d += 1) {
    const double at = x(std::pow(10, d));
    s << "<line x1='" << at << "' y1='" << y0_ + top << "' x2='" << at << "' y2='" << y0_ + top + ph
      << "' stroke='#ddd'/>\n";
    s << "<text x='" << at << "' y='" << y0_ + top + ph + 18 << "' text-anchor='middle'>1e" << static_cast<int>(d)
      << "</text>\n";
  }
  for (double d = y_decade0_; d <= y_decade1_ + 1e-9; d += 1) {
    const double at = y(std::pow(10, d));
    s << "<line x1='" << x0_ + left << "' y1='" << at << "' x2='" << x0_ + left + pw << "' y2='" << at
      << "' stroke='#ddd'/>\n";
    s << "<text x='" << x0_ + left - 6 << "' y='" << at + 4 << "' text-anchor='end'>1e" << static_cast<int>(d)
      << "</text>\n";
  }
  s << "<text x='" << x0_ + left + pw / 2 << "' y='" << y0_ + height - 12 << "' text-anchor='middle'>"
    << escape(x_label) << "</text>\n";
  s << "<text transform='translate(" << x0_ + 16 << "," << y0_ + top + ph / 2 << ") rotate(-90)' text-anchor='middle'>"
    << escape(y_label) << "</text>\n";
}

void polyline(std::ostream& s, const std::vector<std::pair<double, double>>& points, const std::string& colour,
              bool dashed) {
  polyline(s, points, colour, dashed ? "6,3" : "");
}

void polyline(std::ostream& s, const std::vector<std::pair<double, double>>& points, const std::string& colour,
              const char* dasharray) {
  s << "<polyline fill='none' stroke='" << colour << "' stroke-width='1.5'";
  if (*dasharray) s << " stroke-dasharray='" << dasharray << "'";
  s << " points='";
  for (const auto& [x, y] : points) s << x << "," << y << " ";
  s << "'/>\n";
}

void marker(std::ostream& s, int shape, double x, double y, const std::string& colour) {
  switch (shape % 3) {
    case 0: s << "<circle cx='" << x << "' cy='" << y << "' r='3.5' fill='" << colour << "'/>\n"; break;
    case 1:
      s << "<rect x='" << x - 3.5 << "' y='" << y - 3.5 << "' width='7' height='7' fill='" << colour << "'/>\n";
      break;
    default:
      s << "<path d='M" << x << "," << y - 4.5 << " L" << x + 4 << "," << y + 3 << " L" << x - 4 << "," << y + 3
        << " Z' fill='" << colour << "'/>\n";
  }
}

void ring(std::ostream& s, double x, double y) {
  s << "<circle cx='" << x << "' cy='" << y << "' r='8' fill='none' stroke='black' stroke-width='1.5'/>\n";
}

void legend_line(std::ostream& s, double x, double y, const std::string& colour, const std::string& label,
                 bool dashed) {
  legend_line(s, x, y, colour, label, dashed ? "6,3" : "");
}

void legend_line(std::ostream& s, double x, double y, const std::string& colour, const std::string& label,
                 const char* dasharray) {
  s << "<line x1='" << x << "' y1='" << y << "' x2='" << x + 20 << "' y2='" << y << "' stroke='" << colour
    << "' stroke-width='2'";
  if (*dasharray) s << " stroke-dasharray='" << dasharray << "'";
  s << "/><text x='" << x + 24 << "' y='" << y + 4 << "'>" << escape(label) << "</text>\n";
}

}  // namespace nephele::studies
