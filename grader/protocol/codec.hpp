/// @file codec.hpp
/// Encoding of the problem set's values for the protocol (protocol.hpp): one put() and one
/// get() per type, the structs field by field. A Reader never reads past its bytes and
/// rejects a bool that is not 0 or 1: a malformed payload throws DecodeError, whatever sent it.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "problems.hpp"  // the contracts, whose types travel

namespace opspace::protocol {

/// A payload that does not decode: too short, too long, or a value out of its range.
class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Appends encoded values.
class Writer {
 public:
  void raw(const void* data, std::size_t size) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    if (size > 0) std::memcpy(bytes_.data() + at, data, size);
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

/// Reads encoded values from a payload, checking every size.
class Reader {
 public:
  Reader(const unsigned char* data, std::size_t size) : data_(data), size_(size) {}
  void raw(void* out, std::size_t size) {
    if (size > size_ - offset_) throw DecodeError("the message is shorter than its content");
    std::memcpy(out, data_ + offset_, size);
    offset_ += size;
  }
  /// Throws unless every byte was read: an answer is exactly its value.
  void finish() const {
    if (offset_ != size_) throw DecodeError("the message is longer than its content");
  }

 private:
  const unsigned char* data_;
  std::size_t size_;
  std::size_t offset_ = 0;
};

// --- scalars and matrices ------------------------------------------------------------------
inline void put(Writer& w, double v) { w.raw(&v, sizeof v); }
inline void get(Reader& r, double& v) { r.raw(&v, sizeof v); }
inline void put(Writer& w, int v) {
  const std::int32_t x = v;
  w.raw(&x, sizeof x);
}
inline void get(Reader& r, int& v) {
  std::int32_t x = 0;
  r.raw(&x, sizeof x);
  v = x;
}
inline void put(Writer& w, bool v) {
  const unsigned char x = v ? 1 : 0;
  w.raw(&x, 1);
}
inline void get(Reader& r, bool& v) {
  unsigned char x = 0;
  r.raw(&x, 1);
  if (x > 1) throw DecodeError("a true/false value is neither 0 nor 1");
  v = x == 1;
}
/// Enumerations travel as their underlying int; the grader checks the values it reads.
template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
void put(Writer& w, E v) {
  put(w, static_cast<int>(v));
}
template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
void get(Reader& r, E& v) {
  int x = 0;
  get(r, x);
  v = static_cast<E>(x);
}
template <int R, int C, int O>
void put(Writer& w, const Eigen::Matrix<double, R, C, O, R, C>& m) {
  static_assert(R > 0 && C > 0, "only fixed-size matrices travel");
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) put(w, m(i, j));
}
template <int R, int C, int O>
void get(Reader& r, Eigen::Matrix<double, R, C, O, R, C>& m) {
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) get(r, m(i, j));
}
template <class T, std::size_t N>
void put(Writer& w, const std::array<T, N>& a) {
  for (const T& x : a) put(w, x);
}
template <class T, std::size_t N>
void get(Reader& r, std::array<T, N>& a) {
  for (T& x : a) get(r, x);
}

// --- the problem set's structs: each problem's functions.hpp (problems/<key>/) lists their
// fields once, for both directions, as fields(s, f, static_cast<S*>(nullptr)) in the contract's
// namespace, where the calls below find it by argument-dependent lookup: a struct without one
// has neither put() nor get(), and a function that returns it does not compile in the runner.

/// Accepts any field: what put() and get() below use to ask "has T a field list?".
struct AnyField {
  template <class T>
  void operator()(T&) const {}
};

template <class S, class = decltype(fields(std::declval<S&>(), AnyField{}, static_cast<S*>(nullptr)))>
void put(Writer& w, const S& s) {
  fields(s, [&w](const auto& x) { put(w, x); }, static_cast<S*>(nullptr));
}
template <class S, class = decltype(fields(std::declval<S&>(), AnyField{}, static_cast<S*>(nullptr)))>
void get(Reader& r, S& s) {
  fields(s, [&r](auto& x) { get(r, x); }, static_cast<S*>(nullptr));
}

/// Every number of a value, in encoding order, as doubles: to compare two values entry by
/// entry (the grader's diagnosis compares a student's answers with a known mistake's).
inline void flatten(std::vector<double>& out, double v) { out.push_back(v); }
inline void flatten(std::vector<double>& out, int v) { out.push_back(v); }
inline void flatten(std::vector<double>& out, bool v) { out.push_back(v ? 1.0 : 0.0); }
template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
void flatten(std::vector<double>& out, E v) {
  out.push_back(static_cast<double>(static_cast<int>(v)));
}
template <int R, int C, int O>
void flatten(std::vector<double>& out, const Eigen::Matrix<double, R, C, O, R, C>& m) {
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) out.push_back(m(i, j));
}
template <class T, std::size_t N>
void flatten(std::vector<double>& out, const std::array<T, N>& a) {
  for (const T& x : a) flatten(out, x);
}
template <class S, class = decltype(fields(std::declval<S&>(), AnyField{}, static_cast<S*>(nullptr)))>
void flatten(std::vector<double>& out, const S& s) {
  fields(s, [&out](const auto& x) { flatten(out, x); }, static_cast<S*>(nullptr));
}

/// The encoded size of a value of type T (every type above has one fixed size), from the
/// types alone: no value is read.
template <class T>
struct Tag {};
inline std::size_t size_of(Tag<double>) { return sizeof(double); }
inline std::size_t size_of(Tag<int>) { return sizeof(std::int32_t); }
inline std::size_t size_of(Tag<bool>) { return 1; }
template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
std::size_t size_of(Tag<E>) {
  return sizeof(std::int32_t);
}
template <int R, int C, int O>
std::size_t size_of(Tag<Eigen::Matrix<double, R, C, O, R, C>>) {
  return sizeof(double) * R * C;
}
template <class T, std::size_t N>
std::size_t size_of(Tag<std::array<T, N>>) {
  return N * size_of(Tag<T>{});
}
template <class S, class = decltype(fields(std::declval<S&>(), AnyField{}, static_cast<S*>(nullptr)))>
std::size_t size_of(Tag<S>) {
  std::size_t size = 0;
  S* none = nullptr;
  // fields() only names the members here; nothing is read, so a null object is never touched
  // through: each lambda call adds the size of its argument's type.
  alignas(S) unsigned char storage[sizeof(S)];
  fields(*reinterpret_cast<S*>(storage), [&size](auto& x) { size += size_of(Tag<std::decay_t<decltype(x)>>{}); }, none);
  return size;
}

template <class T>
std::size_t encoded_size() {
  return size_of(Tag<T>{});
}

}  // namespace opspace::protocol
