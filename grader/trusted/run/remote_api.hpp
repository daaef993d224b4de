/// @file remote_api.hpp
/// The grader's Hw2Api: each function encodes its arguments, asks the problem's runner and
/// decodes the answer (protocol/codec.hpp), whose size and values were checked on arrival.
#pragma once

#include <string>

#include "run/api.hpp"
#include "run/runner_process.hpp"

namespace opspace::grading {

/// A Hw2Api whose functions of problem `key` ("1a", ... "4") are answered by `runner`; the
/// other problems' functions stay empty. Its identity is new on every call.
Hw2Api remote_api(const std::string& key, RunnerProcess& runner);

}  // namespace opspace::grading
