/// @file problems/5/functions.hpp
/// Problem 5's student functions (problems/5/contract.hpp), one row each: the only list of
/// them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp what
/// a row holds.
#pragma once

#include <opspace/hw2/p5.hpp>

#define OPSPACE_P5_FUNCTIONS(F) F(p5, 0x0501, kP5TaskInertia, task_inertia) /* Lambda = (J A^-1 J^T)^-1 */
