#include "report/html_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/student_text.hpp"

namespace opspace::grading {

std::string html_text(const std::string& s) {
  std::string out;
  for (const char c : html_escape(s)) {
    if (c == '"') out += "&quot;";
    else if (c == '\'') out += "&#39;";
    else out += c;
  }
  return out;
}

std::string html_number(double v, int digits) {
  if (!std::isfinite(v)) return "NaN";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string exact_number(double v) {
  if (!std::isfinite(v)) return "NaN";
  char buffer[40];
  for (int digits = 6; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (std::strtod(buffer, nullptr) == v) return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string joined_numbers(const std::vector<double>& values, int digits) {
  std::string out;
  for (const double v : values) out += (out.empty() ? "" : " ") + (digits > 16 ? exact_number(v) : html_number(v, digits));
  return out;
}

}  // namespace opspace::grading
