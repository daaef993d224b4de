#include "run/recording.hpp"

#include <cstddef>
#include <functional>

#include "protocol/codec.hpp"
#include "run/functions.hpp"

namespace opspace::grading {

namespace {

constexpr std::size_t kFirstCalls = 32, kMaxCalls = 200;
constexpr long kStride = 100;

// The first kFirstCalls calls, then every kStride-th, at most kMaxCalls.
bool record_this(const Recording& r) {
  if (r.calls.size() >= kMaxCalls) return false;
  return r.calls.size() < kFirstCalls || r.seen % kStride == 0;
}

template <class R, class... A>
void wrap(std::function<R(A...)>& slot, protocol::Function function, Recording& recording) {
  if (!slot) return;
  slot = [inner = slot, function, &recording](A... args) -> R {
    R value = inner(args...);
    if (record_this(recording)) {
      protocol::Writer in, out;
      (protocol::put(in, args), ...);
      protocol::put(out, value);
      recording.calls.push_back({function, in.bytes(), out.bytes()});
    }
    ++recording.seen;
    return value;
  };
}

}  // namespace

Hw2Api recorded(const Hw2Api& api, Recording& recording) {
  Hw2Api out = api;
  for_each_function(out, [&recording](protocol::Function f, auto& slot) { wrap(slot, f, recording); });
  return out;
}

}  // namespace opspace::grading
