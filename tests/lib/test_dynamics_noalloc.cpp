// A control tick must not touch the heap: once a Data exists, the kinematics and dynamics
// calls allocate nothing. Every heap allocation of the process is counted: by interposing
// malloc and friends (glibc), or, under AddressSanitizer, which owns malloc, by its hooks.
// Eigen allocates with malloc and operator new ends in malloc, so both are seen.
#include <doctest/doctest.h>

#include <atomic>
#include <cstddef>
#include <string>

#include "opspace/dynamics.hpp"
#include "opspace/kinematics.hpp"
#include "opspace/urdf.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// Declared by hand: GCC ships the ASan runtime but not <sanitizer/allocator_interface.h>.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*)(const volatile void*, std::size_t),
                                                         void (*)(const volatile void*));
namespace {
void count_malloc(const volatile void*, std::size_t) { ++g_allocations; }
void ignore_free(const volatile void*) {}
const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(count_malloc, ignore_free);
}  // namespace
#else
// glibc's own allocator entry points, which our definitions forward to.
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);
extern "C" void* __libc_memalign(std::size_t, std::size_t);
extern "C" {
void* malloc(std::size_t n) {
  ++g_allocations;
  return __libc_malloc(n);
}
void* calloc(std::size_t count, std::size_t n) {
  ++g_allocations;
  return __libc_calloc(count, n);
}
void* realloc(void* p, std::size_t n) {
  ++g_allocations;
  return __libc_realloc(p, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  ++g_allocations;
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** p, std::size_t alignment, std::size_t n) {
  ++g_allocations;
  *p = __libc_memalign(alignment, n);
  return *p ? 0 : 12;  // ENOMEM
}
}
#endif

using namespace opspace;

namespace {

/// Number of heap allocations made by f().
template <class F>
long allocations_in(F&& f) {
  const long before = g_allocations.load();
  f();
  return g_allocations.load() - before;
}

}  // namespace

TEST_CASE("the allocation counter sees Eigen's heap allocations") {
  // Positive control: a dynamic-size vector must be counted, or the next test proves nothing.
  long size = 0;
  const long n = allocations_in([&] {
    Eigen::VectorXd v = Eigen::VectorXd::Ones(100);
    size = v.size();
  });
  CHECK(size == 100);
  CHECK_MESSAGE(n >= 1, "the counter missed a VectorXd allocation");
}

TEST_CASE("kinematics and dynamics allocate nothing once Data exists") {
  for (const char* file : {"puma.urdf", "iiwa7.urdf", "pp.urdf", "rrr.urdf"}) {
    CAPTURE(file);
    const Model model = load_urdf(robot_path(file));
    Data data(model);
    const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(model.dof(), -0.7, 0.9);
    const Eigen::VectorXd qdot = Eigen::VectorXd::LinSpaced(model.dof(), 0.5, -0.4);
    const Eigen::VectorXd tau = Eigen::VectorXd::LinSpaced(model.dof(), 1.0, -1.0);
    Matrix6Xd J0(6, model.dof());
    const int tip = static_cast<int>(model.frames.size()) - 1;
    const Eigen::Vector3d p(0.1, 0.0, 0.05);
    Vector6d sink = Vector6d::Zero();

    const long n = allocations_in([&] {
      forward_kinematics(model, data, q);
      sink += Vector6d::Constant(point_position(model, data, tip, p).sum());
      point_jacobian(model, data, tip, p, J0);
      sink += point_velocity(model, data, tip, p, qdot);
      sink += point_jacobian_dot_times_qdot(model, data, tip, p, q, qdot);
      crba(model, data, q);
      generalized_gravity(model, data, q);
      coriolis_centrifugal(model, data, q, qdot);
      rnea(model, data, q, qdot, tau);
      forward_dynamics(model, data, q, qdot, tau);
    });
    CHECK(sink.allFinite());
    CHECK_MESSAGE(n == 0, "a control-loop call allocated ", n, " times: size the workspace in Data instead");
  }
}
