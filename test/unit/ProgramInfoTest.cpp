// The description a compiled object carries (runtime/ncrt.h ProgramInfo) and its checksum
// trailer: round trip, and every damaged form refused without reading past its bytes.
#include "runtime/ncrt.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

using namespace ncc::ncrt;

static ProgramInfo sample() {
  ProgramInfo info;
  info.abi = abiFingerprint();
  info.nccVersion = "0.1.0";
  info.machineName = "examples/machines/lathe.toml";
  info.machineText = "[machine]\nname = \"lathe\"\n";
  info.files = {{"part.nc", textHash("G0 X1\n")}, {"sub/O1000.nc", 42}};
  return info;
}

TEST(ProgramInfo, RoundTrips) {
  std::string bytes = encodeProgramInfo(sample());
  ProgramInfo back;
  std::string err;
  ASSERT_TRUE(decodeProgramInfo(reinterpret_cast<const unsigned char *>(bytes.data()), bytes.size(), back, err)) << err;
  EXPECT_EQ(back.machineName, "examples/machines/lathe.toml");
  EXPECT_EQ(back.machineText, sample().machineText);
  ASSERT_EQ(back.files.size(), 2u);
  EXPECT_EQ(back.files[1].name, "sub/O1000.nc");
  EXPECT_EQ(back.files[0].hash, textHash("G0 X1\n"));
}

// A copy on the heap of exactly n bytes, so that AddressSanitizer sees any read past them.
TEST(ProgramInfo, EveryTruncationIsRefused) {
  std::string bytes = encodeProgramInfo(sample());
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::unique_ptr<unsigned char[]> copy(new unsigned char[n ? n : 1]);
    std::memcpy(copy.get(), bytes.data(), n);
    ProgramInfo out;
    std::string err;
    EXPECT_FALSE(decodeProgramInfo(copy.get(), n, out, err)) << n;
    EXPECT_FALSE(err.empty());
    if (n < 16) continue;
    uint64_t size = n;  // a header that agrees with the truncated length: the fields run out
    std::memcpy(copy.get() + 8, &size, 8);
    EXPECT_FALSE(decodeProgramInfo(copy.get(), n, out, err)) << n;
  }
}

TEST(ProgramInfo, AnotherAbiIsStale) {
  ProgramInfo info = sample();
  std::string bytes = encodeProgramInfo(info);
  bytes[16] ^= 1;  // the abi field
  ProgramInfo out;
  std::string err;
  EXPECT_FALSE(decodeProgramInfo(reinterpret_cast<const unsigned char *>(bytes.data()), bytes.size(), out, err));
  EXPECT_NE(err.find("compiled by another ncc (0.1.0"), std::string::npos) << err;
}

TEST(ProgramInfo, TrailerCoversEveryByte) {
  std::string object = "\x7f" "ELF some object bytes";
  std::string file = object + objectTrailer(object);
  EXPECT_TRUE(hasObjectTrailer(file));
  for (size_t i = 0; i < file.size(); ++i) {
    std::string bad = file;
    bad[i] ^= 0x20;
    EXPECT_FALSE(hasObjectTrailer(bad)) << i;
  }
  EXPECT_FALSE(hasObjectTrailer(object));
  EXPECT_FALSE(hasObjectTrailer(""));
}
