/// @file html_text.hpp
/// Text and numbers as the grader's pages write them (the report's page, report_html.hpp; the
/// class page, class/class_page.hpp).
#pragma once

#include <string>
#include <vector>

namespace opspace::grading {

/// `s` for an HTML element or a quoted attribute: & < > " ' escaped (common/student_text.hpp).
std::string html_text(const std::string& s);

/// v in `digits` significant digits ("%g"); "NaN" when it is not finite.
std::string html_number(double v, int digits);

/// v in the fewest significant digits (up to 17) that read back as v: a data- attribute's
/// number, which the tests compare with the verdict's to the last bit.
std::string exact_number(double v);

/// "0.01 0.02 ...": a series' values for a data- attribute (`digits` over 16: exact_number's).
std::string joined_numbers(const std::vector<double>& values, int digits);

}  // namespace opspace::grading
