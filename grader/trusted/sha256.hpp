/// @file sha256.hpp
/// SHA-256 (FIPS 180-4), the key of the grader's cache of built runners: with a cryptographic
/// hash, no exercise file can be written to share another file's key, and with it another
/// student's runner (a 64-bit non-cryptographic hash allows that).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace opspace::grading {

/// SHA-256 of bytes given in pieces: Sha256().add(a).add(b).hex() hashes a + b.
class Sha256 {
 public:
  Sha256& add(const std::string& bytes);
  /// The digest, 64 lowercase hexadecimal digits. Pads and ends the message: call it once.
  std::string hex();

 private:
  void compress(const unsigned char* block);
  // FIPS 180-4 5.3.3: the first 32 bits of the fractional parts of the square roots of the
  // first eight primes.
  std::array<std::uint32_t, 8> h_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                     0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::array<unsigned char, 64> block_{};
  std::size_t used_ = 0;       ///< bytes waiting in block_
  std::uint64_t length_ = 0;   ///< message length in bytes
};

}  // namespace opspace::grading
