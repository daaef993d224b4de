#include "opspace/visuals/plot.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace opspace::plot {

namespace fs = std::filesystem;

Series& Panel::add(std::string title_, std::vector<double> x, std::vector<double> y, Line line) {
  if (x.size() != y.size()) {
    throw std::invalid_argument("plot series '" + title_ + "': " + std::to_string(x.size()) + " x values, " +
                                std::to_string(y.size()) + " y values");
  }
  series.push_back({std::move(title_), std::move(x), std::move(y), line, ""});
  return series.back();
}

Panel& Panel::level(std::string title_, double y) {
  levels.push_back({std::move(title_), y, Level{}.color});
  return *this;
}

Panel& Figure::panel(std::string title_, std::string ylabel) {
  panels.push_back({});
  panels.back().title = std::move(title_);
  panels.back().ylabel = std::move(ylabel);
  return panels.back();
}

namespace {

bool executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

/// A gnuplot double-quoted string literal.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// A gnuplot single-quoted string (file names): only ' needs doubling.
std::string file_literal(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

/// A POSIX shell single-quoted word.
std::string shell_word(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void write_data(const Figure& f, const fs::path& path, std::size_t max_points) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write the plot data " + path.string());
  out << "# " << f.title << ": one block per series (gnuplot 'index'), columns x y\n" << std::setprecision(9);
  std::vector<double> x, y;
  bool first = true;
  for (const Panel& p : f.panels) {
    for (const Series& s : p.series) {
      if (!first) out << "\n\n";
      first = false;
      out << "# " << s.title << "\n";
      decimate(s.x, s.y, max_points, x, y);
      bool any = false;
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
        out << x[i] << ' ' << y[i] << '\n';
        any = true;
      }
      // gnuplot stops on an empty block ("no data"): an unplottable point keeps the script valid.
      if (!any) out << "0 NaN\n";
    }
  }
  if (!out) throw std::runtime_error("cannot write the plot data " + path.string());
}

void write_body(std::ostream& gp, const Figure& f, const std::string& data_file) {
  const int columns = std::max(1, f.columns);
  const int rows = static_cast<int>((f.panels.size() + columns - 1) / columns);
  gp << "set multiplot layout " << rows << "," << columns << " title " << quoted(f.title)
     << " font \",13\"\n";
  int index = 0;
  for (const Panel& p : f.panels) {
    gp << "set title " << quoted(p.title) << "\n"
       << "set xlabel " << quoted(f.xlabel) << "\n"
       << "set ylabel " << quoted(p.ylabel) << "\n"
       << (p.log_y ? "set logscale y\n" : "unset logscale y\n") << "plot ";
    bool first = true;
    for (const Series& s : p.series) {
      gp << (first ? "" : ", \\\n     ") << file_literal(data_file) << " index " << index++
         << " using 1:2 with lines lw 1.6 dt " << (s.line == Line::kDashed ? 2 : 1);
      if (!s.color.empty()) gp << " lc rgb " << quoted(s.color);
      gp << (s.title.empty() ? " notitle" : " title " + quoted(s.title));
      first = false;
    }
    for (const Level& l : p.levels) {
      gp << (first ? "" : ", \\\n     ") << std::setprecision(12) << l.y << " with lines lw 1.2 dt 3 lc rgb "
         << quoted(l.color) << (l.title.empty() ? " notitle" : " title " + quoted(l.title));
      first = false;
    }
    if (first) gp << "NaN notitle";
    gp << "\n";
  }
  gp << "unset multiplot\n";
}

void write_script(const Figure& f, const fs::path& path, const std::string& stem, bool svg) {
  std::ofstream gp(path);
  if (!gp) throw std::runtime_error("cannot write the gnuplot script " + path.string());
  const int rows = static_cast<int>((f.panels.size() + std::max(1, f.columns) - 1) / std::max(1, f.columns));
  const int height = std::max(1, rows) * f.row_height + 40;
  // The legend sits right of each panel: as wide as the longest entry plus its line sample.
  std::size_t longest = 4;
  for (const Panel& p : f.panels) {
    for (const Series& s : p.series) longest = std::max(longest, s.title.size());
    for (const Level& l : p.levels) longest = std::max(longest, l.title.size());
  }
  gp << "# " << f.title << "\n"
     << "# Written by opspace (lib/src/visuals/plot.cpp). Redraw from this folder: gnuplot " << stem << ".gp\n"
     << "set encoding utf8\n"
     << "set grid lc rgb '#dddddd'\n"
     << "set key outside right top samplen 2\n"
     << "set border lc rgb '#555555'\n"
     // Fixed margins: the panels of a figure line up whatever their tick labels and legends.
     << "set lmargin 12\n"
     << "set rmargin " << longest + 8 << "\n";
  gp << "set terminal pngcairo noenhanced size " << f.width << "," << height << " font 'sans,10'\n"
     << "set output " << file_literal(stem + ".png") << "\n";
  write_body(gp, f, stem + ".dat");
  if (svg) {
    gp << "set terminal svg noenhanced size " << f.width << "," << height << " font 'sans,11' background '#ffffff'\n"
       << "set output " << file_literal(stem + ".svg") << "\n";
    write_body(gp, f, stem + ".dat");
  }
  gp << "unset output\n";
  if (!gp) throw std::runtime_error("cannot write the gnuplot script " + path.string());
}

std::string tail_of(const fs::path& log, std::size_t max_chars) {
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  if (s.size() > max_chars) s = "..." + s.substr(s.size() - max_chars);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

std::string find_gnuplot() {
  if (const char* forced = std::getenv("OPSPACE_GNUPLOT")) {
    return executable(forced) ? std::string(forced) : std::string();
  }
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "gnuplot";
    if (executable(candidate)) return candidate.string();
  }
  return "";
}

void decimate(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points,
              std::vector<double>& x_out, std::vector<double>& y_out) {
  x_out.clear();
  y_out.clear();
  const std::size_t n = std::min(x.size(), y.size());
  if (n <= max_points || max_points < 4) {
    x_out.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
    y_out.assign(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n));
    return;
  }
  // Buckets of `width` samples, each giving its minimum and maximum: 2 points per bucket.
  const std::size_t width = (2 * n + max_points - 1) / max_points;
  for (std::size_t start = 0; start < n; start += width) {
    const std::size_t end = std::min(n, start + width);
    std::size_t lo = start, hi = start;
    for (std::size_t i = start; i < end; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    const std::size_t a = std::min(lo, hi), b = std::max(lo, hi);
    x_out.push_back(x[a]);
    y_out.push_back(y[a]);
    if (b != a) {
      x_out.push_back(x[b]);
      y_out.push_back(y[b]);
    }
  }
}

Output render(const std::vector<Figure>& figures, const std::string& prefix, const Options& options) {
  Output result;
  const fs::path base(prefix);
  const fs::path dir = base.parent_path().empty() ? fs::path(".") : base.parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);
  const std::string gnuplot = find_gnuplot();
  std::vector<std::string> failures;
  for (const Figure& f : figures) {
    const std::string stem = base.filename().string() + "-" + f.name;
    write_data(f, dir / (stem + ".dat"), options.max_points);
    write_script(f, dir / (stem + ".gp"), stem, options.svg);
    result.scripts.push_back((dir / (stem + ".gp")).string());
    if (gnuplot.empty()) continue;
    // Relative names in the script: run it from its folder, so the folder can be moved.
    const fs::path log = dir / (stem + ".gnuplot.log");
    const std::string command = "cd " + shell_word(dir.string()) + " && " + shell_word(gnuplot) + " " +
                                shell_word(stem + ".gp") + " > " + shell_word(log.filename().string()) + " 2>&1";
    const int status = std::system(command.c_str());
    const fs::path png = dir / (stem + ".png"), svg = dir / (stem + ".svg");
    const bool drawn = status == 0 && fs::file_size(png, ec) > 0 && !ec;
    if (!drawn) {
      failures.push_back(stem + " (gnuplot said: " + tail_of(log, 300) + "; log " + log.string() + ")");
      continue;
    }
    fs::remove(log, ec);
    result.images.push_back(png.string());
    if (options.svg && fs::file_size(svg, ec) > 0 && !ec) result.images.push_back(svg.string());
  }
  if (gnuplot.empty() && !figures.empty()) {
    result.skipped = "no plots: gnuplot was not found (apt-get install gnuplot-nox; bash scripts/test installs it). "
                     "The data and gnuplot scripts are written: run them with gnuplot later";
  } else if (!failures.empty()) {
    std::string joined;
    for (const std::string& f : failures) joined += (joined.empty() ? "" : "; ") + f;
    result.skipped = "gnuplot failed on " + joined;
  }
  return result;
}

}  // namespace opspace::plot
