/// @file sha256.hpp
/// SHA-256 (FIPS 180-4), the key of the grader's cache of built runners: with a cryptographic
/// hash, no exercise file can be written to share another file's key, and with it another
/// student's runner (a 64-bit non-cryptographic hash allows that). Computed by OpenSSL's
/// libcrypto (EVP digest API), not by our own code.
#pragma once

#include <memory>
#include <string>

struct evp_md_ctx_st;

namespace opspace::grading {

/// SHA-256 of bytes given in pieces: Sha256().add(a).add(b).hex() hashes a + b.
/// Throws std::runtime_error if libcrypto fails (it does not, short of memory).
class Sha256 {
 public:
  Sha256();
  Sha256& add(const std::string& bytes);
  /// The digest, 64 lowercase hexadecimal digits. Ends the message: call it once.
  std::string hex();

 private:
  struct Free {
    void operator()(evp_md_ctx_st* context) const;
  };
  std::unique_ptr<evp_md_ctx_st, Free> context_;
};

}  // namespace opspace::grading
