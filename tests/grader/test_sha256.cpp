// The grader's cache key (grader/trusted/common/sha256.cpp: libcrypto's SHA-256 behind our
// add()/hex()) against published digests.
#include <doctest/doctest.h>

#include <string>

#include "common/sha256.hpp"

using opspace::grading::Sha256;

namespace {
std::string sha256(const std::string& message) { return Sha256().add(message).hex(); }
}  // namespace

TEST_CASE("SHA-256 gives the digests of FIPS 180-2's examples") {
  // FIPS 180-2, appendix B.1 (one block), B.2 (two blocks) and B.3 (a million 'a').
  CHECK(sha256("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // NIST's test vectors (SHA256ShortMsg.rsp, Len = 0): the empty message.
  CHECK(sha256("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST_CASE("SHA-256 pads messages that end on either side of a block's last 8 bytes") {
  // 55 bytes leave room for the 1 bit and the length in one block; 56 to 63 need a second
  // block; 64 and 120 fill a block exactly. The digests are those of GNU coreutils' sha256sum
  // 9.1 (gnulib's own SHA-256, not OpenSSL's), an independent implementation.
  CHECK_MESSAGE(sha256(std::string(55, 'a')) == "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318", "55 bytes");
  CHECK_MESSAGE(sha256(std::string(56, 'a')) == "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a", "56 bytes");
  CHECK_MESSAGE(sha256(std::string(63, 'a')) == "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34", "63 bytes");
  CHECK_MESSAGE(sha256(std::string(64, 'a')) == "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb", "64 bytes");
  CHECK_MESSAGE(sha256(std::string(120, 'a')) == "2f3d335432c70b580af0e8e1b3674a7c020d683aa5f73aaaedfdc55af904c21c", "120 bytes");
}

TEST_CASE("SHA-256 of a message added in pieces is that of the whole message") {
  // The cache key is added field by field: the cut points must not matter.
  const std::string whole = std::string(70, 'x') + "exercises/p1b.cpp" + std::string(130, '\n');
  for (std::size_t cut : {0, 1, 55, 64, 65, 100, 217}) {
    CAPTURE(cut);
    CHECK(Sha256().add(whole.substr(0, cut)).add(whole.substr(cut)).hex() == sha256(whole));
  }
}
