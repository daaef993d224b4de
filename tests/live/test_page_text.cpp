// What each problem's live page says above the run (problems/*/run/lab.cpp, issue 46): its title and
// subtitle state what the run shows, measured, never a promise that a student's controller may
// break (1b's stub once read "PART3's tip holds" with the tip 1136 mm off).
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <problems/1b/contract.hpp>
#include <problems/2/contract.hpp>
#include <problems/3/contract.hpp>
#include <problems/4/contract.hpp>
#include <problems/1b/run/lab.hpp>
#include <problems/2/run/lab.hpp>
#include <problems/3/run/lab.hpp>
#include <problems/4/run/lab.hpp>

using namespace opspace;

namespace {

// Words that claim what the run does rather than show it.
const char* const kPromises[] = {"holds", "hold ", "stays", "keeps", "comes back", "returns", "wanders", "tracks",
                                 "follows", "within"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// The plot series the subtitle's "{K}" name, in order (K: one or more digits). Read by hand:
// GCC 12 warns about <regex>'s automaton under the sanitizers, where warnings are errors.
std::vector<int> placeholders(const std::string& subtitle) {
  std::vector<int> k;
  for (std::size_t open = subtitle.find('{'); open != std::string::npos; open = subtitle.find('{', open + 1)) {
    std::size_t end = open + 1;
    while (end < subtitle.size() && std::isdigit(static_cast<unsigned char>(subtitle[end]))) ++end;
    if (end > open + 1 && end < subtitle.size() && subtitle[end] == '}')
      k.push_back(std::stoi(subtitle.substr(open + 1, end - open - 1)));
  }
  return k;
}

int series_count(const live::LabInfo& info) {
  int n = 0;
  for (const live::Plot& p : info.plots) n += static_cast<int>(p.series.size());
  return n;
}

void check_page_text(const live::Lab& lab) {
  const live::LabInfo& info = lab.info();
  INFO(info.program << ": '" << info.title << "' / '" << info.subtitle << "'");
  const std::string text = lower(info.title + " " + info.subtitle);
  for (const char* word : kPromises) CHECK_MESSAGE(text.find(word) == std::string::npos, "a promise: " << std::string(word));
  const std::vector<int> fields = placeholders(info.subtitle);
  CHECK_MESSAGE(!fields.empty(), "the subtitle shows no measured value ({K})");
  for (const int k : fields) CHECK_MESSAGE(k < series_count(info), "{" << k << "} names no plot series");
}

}  // namespace

TEST_CASE("each live page's title and subtitle show measured values and promise nothing") {
  // Seen to fail before the subtitles changed: 1b's "holds", "wanders"; 2's "tracks", "holds";
  // 3's "comes back"; and no {K} in any of them.
  const live::P1bLab p1b("hw2-p1", hw2::p1b::Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  check_page_text(p1b);
  // 1b's first value is the tip error the student watches: |x - x_d|, in mm.
  const std::vector<int> fields = placeholders(p1b.info().subtitle);
  REQUIRE(!fields.empty());
  CHECK(fields[0] == 0);
  CHECK(p1b.info().plots[0].series[0].label == "measured |x - x_d|");
  CHECK(p1b.info().subtitle.find("|x - x_d| = {0} mm") != std::string::npos);
  check_page_text(live::P2Lab("hw2-p2", &hw2::p2::control, &hw2::p2::desired_acceleration));
  check_page_text(live::P3Lab("hw2-p3", &hw2::p3::control));
  check_page_text(live::P4Lab("hw2-p4", hw2::p4::Target::kAlongZ0, &hw2::p4::control));
}
