/// @file student_text.hpp
/// Text from the student's side (what their code prints, their exception texts, the compiler's
/// messages about their file) shown in the report and in results.json. It is hostile input: it
/// is always marked as theirs (between quotes, or behind "| "), never starts a line of the
/// report, and shows escaped whatever could break or reorder a line: newlines, C0 and C1
/// control characters, DEL, the bidirectional formatting characters (U+061C, U+200E/F,
/// U+202A-E, U+2066-9), the line and paragraph separators U+2028/9, and invalid UTF-8.
#pragma once

#include <cstddef>
#include <string>

namespace opspace::grading {

/// `text` with every character above escaped: "\n", "\t", "\x1b" for bytes and invalid
/// UTF-8, "\u202e" for code points. With `keep_newlines` a newline stays a newline (for a
/// quoted block). Backslash and double quote are escaped too when `in_quotes`.
std::string escape_student_text(const std::string& text, bool keep_newlines, bool in_quotes);

/// One line: the first `limit` bytes of `text`, escaped, between double quotes, followed by
/// "[... N more bytes not shown]" when `total` (the text's length before any cut) is larger.
std::string student_line(const std::string& text, std::size_t limit, std::size_t total);

/// Several lines: the first `limit` bytes of `text`, escaped but for the newlines, with the
/// same note when `total` is larger. Show it with quote_block.
std::string student_block(const std::string& text, std::size_t limit, std::size_t total);

/// `block` with each of its lines behind `indent` + "| " and ended by a newline.
std::string quote_block(const std::string& block, const std::string& indent);

/// `text` with & < > written &amp; &lt; &gt;, for a page: results.json declares its texts
/// "text" (output_format), which Gradescope shows as they are, and this keeps a tag or an
/// entity from the student's side inert wherever a viewer renders HTML or markdown anyway.
std::string html_escape(const std::string& text);

}  // namespace opspace::grading
