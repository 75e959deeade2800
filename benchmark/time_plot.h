// A log-log SVG plot of run time against vertex count, one polyline per method.

#ifndef NP_BENCHMARK_TIME_PLOT_H
#define NP_BENCHMARK_TIME_PLOT_H

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace np_benchmark {

inline void write_time_plot(const std::string& path,
                            std::map<std::string, std::vector<std::pair<double, double> > > series)
{
  const double width = 760, height = 480, left = 70, right = 190, top = 20, bottom = 50;
  double x_lo = 1e300, x_hi = 0, y_lo = 1e300, y_hi = 0;
  for(auto& [name, points] : series)
  {
    std::sort(points.begin(), points.end());
    for(const auto& [x, y] : points)
    {
      x_lo = std::min(x_lo, x); x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, std::max(y, 1e-4)); y_hi = std::max(y_hi, std::max(y, 1e-4));
    }
  }
  if(x_hi <= 0) return;
  const double lx0 = std::floor(std::log10(x_lo)), lx1 = std::ceil(std::log10(x_hi)) + (x_lo == x_hi ? 1 : 0);
  const double ly0 = std::floor(std::log10(y_lo)), ly1 = std::ceil(std::log10(y_hi)) + (y_lo == y_hi ? 1 : 0);
  auto px = [&](double x) { return left + (std::log10(x) - lx0) / (lx1 - lx0) * (width - left - right); };
  auto py = [&](double y) { return height - bottom - (std::log10(std::max(y, 1e-4)) - ly0) / (ly1 - ly0) * (height - top - bottom); };
  const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#17becf", "#bcbd22"};

  std::ofstream svg(path);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for(double e = lx0; e <= lx1; ++e)
    svg << "<line x1='" << px(std::pow(10, e)) << "' x2='" << px(std::pow(10, e)) << "' y1='" << top << "' y2='"
        << height - bottom << "' stroke='#ddd'/><text x='" << px(std::pow(10, e)) << "' y='" << height - bottom + 18
        << "' text-anchor='middle'>1e" << e << "</text>\n";
  for(double e = ly0; e <= ly1; ++e)
    svg << "<line x1='" << left << "' x2='" << width - right << "' y1='" << py(std::pow(10, e)) << "' y2='"
        << py(std::pow(10, e)) << "' stroke='#ddd'/><text x='" << left - 8 << "' y='" << py(std::pow(10, e)) + 4
        << "' text-anchor='end'>1e" << e << " s</text>\n";
  svg << "<text x='" << (left + width - right) / 2 << "' y='" << height - 10 << "' text-anchor='middle'>vertices</text>\n";
  int k = 0;
  for(const auto& [name, points] : series)
  {
    const char* color = colors[k % 10];
    svg << "<polyline fill='none' stroke='" << color << "' stroke-width='2' points='";
    for(const auto& [x, y] : points) svg << px(x) << ',' << py(y) << ' ';
    svg << "'/>\n";
    for(const auto& [x, y] : points)
      svg << "<circle cx='" << px(x) << "' cy='" << py(y) << "' r='3' fill='" << color << "'/>\n";
    svg << "<text x='" << width - right + 12 << "' y='" << top + 16 * (k + 1) << "' fill='" << color << "'>"
        << name << "</text>\n";
    ++k;
  }
  svg << "</svg>\n";
}

} // namespace np_benchmark

#endif
