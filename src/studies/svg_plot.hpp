#pragma once
// Small SVG building blocks shared by the work-precision diagrams (numerics/work_precision.cpp,
// render/render_report.cpp): the document frame, a log-log panel whose axes span whole decades
// around the data, series lines and point markers.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace nephele::studies {

// The XML header, the white background and the title centred at the top.
void begin_document(std::ostream& s, double width, double height, const std::string& title);
void end_document(std::ostream& s);

// `text` with &, <, > and ' escaped for XML text and single-quoted attributes.
std::string escape(const std::string& text);

// A 520 x 400 log-log panel with its top left corner at (x0, y0). Values below the floors are
// drawn at the floors (log scales cannot show zero).
class LogLogPanel {
 public:
  static constexpr double width = 520, height = 400, left = 70, bottom = 50, top = 30, right = 20;

  LogLogPanel(double x0, double y0, const std::vector<double>& xs, const std::vector<double>& ys, double x_floor = 1e-3,
              double y_floor = 1e-9);

  double x(double value) const;  // document coordinates of a data value
  double y(double value) const;

  // The frame, a grid line and a 1eN label at every decade, and the two axis titles.
  void draw_axes(std::ostream& s, const std::string& x_label, const std::string& y_label) const;

 private:
  double x0_, y0_, x_floor_, y_floor_;
  double x_decade0_, x_decade1_, y_decade0_, y_decade1_;
};

// A polyline through points given in document coordinates; `dashed` draws it 6,3 dashed.
void polyline(std::ostream& s, const std::vector<std::pair<double, double>>& points, const std::string& colour,
              bool dashed = false);
// The same with an SVG stroke-dasharray ("" solid, "6,3" as `dashed`, "2,2" dotted).
void polyline(std::ostream& s, const std::vector<std::pair<double, double>>& points, const std::string& colour,
              const char* dasharray);
// A filled marker: 0 circle, 1 square, 2 triangle (taken modulo 3).
void marker(std::ostream& s, int shape, double x, double y, const std::string& colour);
// The black ring that marks a default configuration.
void ring(std::ostream& s, double x, double y);
// A short legend line with its label.
void legend_line(std::ostream& s, double x, double y, const std::string& colour, const std::string& label,
                 bool dashed = false);
void legend_line(std::ostream& s, double x, double y, const std::string& colour, const std::string& label,
                 const char* dasharray);

}  // namespace nephele::studies
