// How the grader shows text from the student's side (grader/trusted/common/student_text.cpp).
// The code points and their UTF-8 bytes are Unicode's (UnicodeData.txt, Bidi_Class); the rule
// under test is that none of them reaches the report raw, and nothing else is changed.
#include <doctest/doctest.h>

#include <string>

#include "common/student_text.hpp"

using opspace::grading::escape_student_text;
using opspace::grading::quote_block;
using opspace::grading::student_block;

namespace {
std::string line(const std::string& text) { return opspace::grading::student_line(text, 200, text.size()); }
}  // namespace

TEST_CASE("a student's line is quoted, with newlines and control characters escaped") {
  CHECK(line("index out of range") == "\"index out of range\"");
  CHECK(line("a\nTotal: 97 / 97 points") == "\"a\\nTotal: 97 / 97 points\"");
  CHECK_MESSAGE(line("say \"hi\" \\ bye") == "\"say \\\"hi\\\" \\\\ bye\"", "a quote inside cannot end the quoting");
  CHECK(line(std::string("tab\tnul") + '\0' + "esc\x1b" + "del\x7f") == "\"tab\\tnul\\x00esc\\x1bdel\\x7f\"");
  CHECK_MESSAGE(opspace::grading::student_line("0123456789", 4, 10) == "\"0123\" [... 6 more bytes not shown]",
                "cut at the limit");
}

TEST_CASE("code points that break or reorder a line are shown escaped, others as they are") {
  // C1 controls U+0080 and U+0085 (NEL), the Arabic letter mark U+061C, LRM/RLM U+200E/F,
  // the embeddings and overrides U+202A-E, the isolates U+2066-9, U+2028 and U+2029.
  CHECK(escape_student_text("\xc2\x80\xc2\x85", false, false) == "\\u0080\\u0085");
  CHECK(escape_student_text("\xd8\x9c\xe2\x80\x8e\xe2\x80\x8f", false, false) == "\\u061c\\u200e\\u200f");
  CHECK(escape_student_text("\xe2\x80\xaa\xe2\x80\xae", false, false) == "\\u202a\\u202e");
  CHECK(escape_student_text("\xe2\x81\xa6\xe2\x81\xa9", false, false) == "\\u2066\\u2069");
  CHECK(escape_student_text("\xe2\x80\xa8\xe2\x80\xa9", false, false) == "\\u2028\\u2029");
  CHECK_MESSAGE(escape_student_text("\xce\xbb = 0.5 \xe2\x86\x92 \xf0\x9f\x99\x82", false, false) ==
                    "\xce\xbb = 0.5 \xe2\x86\x92 \xf0\x9f\x99\x82",
                "lambda, an arrow and an emoji are printable: kept");
}

TEST_CASE("invalid UTF-8 is shown byte by byte") {
  CHECK_MESSAGE(escape_student_text("\xff", false, false) == "\\xff", "never a UTF-8 byte");
  CHECK_MESSAGE(escape_student_text("\xc0\xaf", false, false) == "\\xc0\\xaf", "an overlong '/'");
  CHECK_MESSAGE(escape_student_text("\xed\xa0\x80", false, false) == "\\xed\\xa0\\x80", "a UTF-16 surrogate");
  CHECK_MESSAGE(escape_student_text("\xf4\x90\x80\x80", false, false) == "\\xf4\\x90\\x80\\x80", "above U+10FFFF");
  CHECK_MESSAGE(escape_student_text("ab\xe2\x80", false, false) == "ab\\xe2\\x80", "a sequence cut at the end");
}

TEST_CASE("a student's block keeps its lines, each behind the quote mark") {
  const std::string text = "hello\nTotal: 97 / 97 points\n\xe2\x80\xa8  PASS\n";
  const std::string block = student_block(text, 100, text.size());
  CHECK(block == "hello\nTotal: 97 / 97 points\n\\u2028  PASS\n");
  CHECK(quote_block(block, "    ") == "    | hello\n    | Total: 97 / 97 points\n    | \\u2028  PASS\n");
  CHECK_MESSAGE(quote_block("a\n\nb", "") == "| a\n| \n| b\n", "an empty line is quoted too");
  CHECK(student_block("0123456789", 4, 10) == "0123\n[... 6 more bytes not shown]");
}
