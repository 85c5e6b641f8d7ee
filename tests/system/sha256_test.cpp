// sha256_hex: FIPS 180-4's example digests, every padding case around a block
// boundary checked against sha256sum's figures, and a long input.

#include "capsim/system/sha256.h"

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include <string>

using capsim::sha256_hex;

TEST(Sha256, GivesTheStandardsExampleDigests) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// 55 bytes leave room for the length in the last block, 56 do not; 64 is a
// whole block followed by a padding block.
TEST(Sha256, PadsAtTheBlockBoundaries) {
  EXPECT_EQ(sha256_hex(std::string(55, 'a')), "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  EXPECT_EQ(sha256_hex(std::string(56, 'a')), "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  EXPECT_EQ(sha256_hex(std::string(64, 'a')), "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
}

TEST(Sha256, ReadsEveryByteIncludingZerosAndHighBytes) {
  const std::string bytes("a\0\xff", 3);
  EXPECT_EQ(sha256_hex(bytes), "2d28501a66adef190c7f5b220994e76d5cc30f1eb165a8ca6cab56dfd57092fe");
}

TEST(Sha256, DigestsAFileAsItsBytes) {
  capsim::testing::TempDir dir;
  std::ofstream(dir / "f.bin", std::ios::binary) << "abc";
  EXPECT_EQ(capsim::file_sha256_hex(dir / "f.bin"), sha256_hex("abc"));
  std::ofstream(dir / "empty.bin", std::ios::binary);
  EXPECT_EQ(capsim::file_sha256_hex(dir / "empty.bin"), sha256_hex(""));
  EXPECT_THROW((void)capsim::file_sha256_hex(dir / "none.bin"), std::runtime_error);
}
