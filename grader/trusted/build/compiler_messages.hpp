/// @file compiler_messages.hpp
/// What the grader reads of a compilation of the student's file: the compiler's first error
/// and its warnings (as the student's text, student_text.hpp), and the files it included.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace opspace::grading {

/// The first `limit` bytes of the file at `path` (and one more, to tell a longer file).
/// Throws std::runtime_error if it cannot be read.
std::string read_at_most(const std::string& path, std::size_t limit);

/// The tool's first error, "p1b.cpp:12:5: error: ...", and the source line below it, with the
/// work folder's name of the file (`work_file`) replaced by the name the student knows
/// (`shown_as`): a grader line that quotes the error (student_line: each test of the problem
/// carries this line), then the source line as a block (student_block) below it. A contract not
/// found by its former path (<opspace/hw2/p<key>.hpp>) is named with today's
/// (<problems/<key>/contract.hpp>) on the grader's line. Errors located in other files are shown
/// only if those files are public headers (under `include_roots`).
/// Empty if `output` holds no error. `tool` names the tool: "compiler", "linker".
std::string first_error(const std::string& output, const std::string& work_file, const std::string& shown_as,
                        const std::vector<std::string>& include_roots, const std::string& tool);

/// The warnings in `output`, one per line, cut to `limit` bytes (the student's text).
std::string warnings_of(const std::string& output, const std::string& work_file, const std::string& shown_as,
                        std::size_t limit);

/// Empty if every file the compilation read (its dependency file `depfile`) is the student's
/// own file or under one of `roots`; else why not.
std::string check_includes(const std::string& depfile, const std::string& work_dir, const std::string& shown_as,
                           const std::vector<std::string>& roots);

}  // namespace opspace::grading
