#include "opspace/programs/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace opspace::programs {

std::string show(double value, const Unit& unit) {
  const double x = value * unit.scale;
  std::ostringstream out;
  if (!std::isfinite(x)) {
    out << x;
  } else if (x == std::round(x) && std::abs(x) < 1e15) {
    out << std::fixed << std::setprecision(0) << x;  // counts, and round bounds: "0", "50"
  } else {
    // Three significant digits, at least the units.
    const int decimals = std::clamp(2 - static_cast<int>(std::floor(std::log10(std::abs(x)))), 0, 6);
    out << std::fixed << std::setprecision(decimals) << x;
  }
  if (*unit.name) out << " " << unit.name;
  return out.str();
}

std::string show_bound(double value, const Unit& unit) {
  std::string s = show(value, unit);
  const std::size_t end = s.find(' ');
  std::string number = s.substr(0, end);
  if (number.find('.') != std::string::npos) {
    number.erase(number.find_last_not_of('0') + 1);
    if (number.back() == '.') number.pop_back();
  }
  return number + (end == std::string::npos ? "" : s.substr(end));
}

std::string joint(int index) { return " (joint " + std::to_string(index + 1) + ")"; }

Verdict::Verdict(std::string reference, std::string value, std::string should)
    : reference_(std::move(reference)), value_(std::move(value)), should_(std::move(should)) {}

void Verdict::section(const std::string& title) {
  Row r;
  r.what = title;
  r.heading = true;
  rows_.push_back(r);
}

void Verdict::at_most(const std::string& what, double value, double bound, double reference, const Unit& unit) {
  const bool ok = value <= bound;  // false for NaN
  row(what, show(value, unit), "<= " + show_bound(bound, unit), show(reference, unit), ok ? "ok" : "MISSES");
}

void Verdict::at_least(const std::string& what, double value, double bound, double reference, const Unit& unit) {
  const bool ok = value >= bound;
  row(what, show(value, unit), ">= " + show_bound(bound, unit), show(reference, unit), ok ? "ok" : "MISSES");
}

void Verdict::shown(const std::string& what, double value, double reference, const Unit& unit) {
  row(what, show(value, unit), "not graded", show(reference, unit));
}

void Verdict::row(const std::string& what, std::string value, std::string should, std::string reference,
                  std::string verdict) {
  if (!verdict.empty() && verdict != "ok") ++misses_;
  rows_.push_back({"  " + what, std::move(value), std::move(should), std::move(reference), std::move(verdict)});
}

void Verdict::note(const std::string& text) {
  Row r;
  r.what = "    " + text;
  r.is_note = true;
  rows_.push_back(r);
}

void Verdict::print(std::ostream& out, const std::string& grade_hint) const {
  std::size_t w[4] = {0, value_.size(), should_.size(), reference_.size()};
  for (const Row& r : rows_) {
    if (r.heading || r.is_note) continue;
    w[0] = std::max(w[0], r.what.size());
    w[1] = std::max(w[1], r.value.size());
    w[2] = std::max(w[2], r.should.size());
    w[3] = std::max(w[3], r.reference.size());
  }
  const auto line = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d,
                        const std::string& e) {
    std::ostringstream s;
    s << std::left << std::setw(static_cast<int>(w[0] + 2)) << a << std::setw(static_cast<int>(w[1] + 2)) << b
      << std::setw(static_cast<int>(w[2] + 2)) << c << std::setw(static_cast<int>(w[3] + 2)) << d << e;
    std::string text = s.str();
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << "\n";
  };
  bool first = true;
  for (const Row& r : rows_) {
    if (r.heading) {
      line(r.what, first ? value_ : "", first ? should_ : "", first ? reference_ : "", "");
      first = false;
    } else if (r.is_note) {
      out << r.what << "\n";
    } else {
      line(r.what, r.value, r.should, r.reference, r.verdict);
    }
  }
  if (misses_ > 0) {
    out << misses_ << (misses_ == 1 ? " of these misses what it should be: " : " of these miss what they should be: ")
        << grade_hint << "\n";
  }
}

}  // namespace opspace::programs
