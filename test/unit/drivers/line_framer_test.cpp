// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/line_framer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace radio_follow::drivers {
namespace {

struct Collected {
  std::vector<std::string> lines;
  std::vector<double> stamps;
  auto sink() {
    return [this](std::string_view line, double t) {
      lines.emplace_back(line);
      stamps.push_back(t);
    };
  }
};

void feed(LineFramer& framer, const std::string& text, double t, Collected& out) {
  framer.feed(text.data(), text.size(), t, out.sink());
}

TEST(LineFramer, AllLineEndingsAndNoEmptyLines) {
  LineFramer framer;
  Collected out;
  feed(framer, "a\r\nb\nc\rd\r\n\r\n\n", 1.0, out);
  EXPECT_EQ(out.lines, (std::vector<std::string>{"a", "b", "c", "d"}));
  EXPECT_EQ(framer.counters().lines, 4u);
  EXPECT_EQ(framer.pending(), "");
}

TEST(LineFramer, KeepsLeftoverAndStampsFirstByte) {
  LineFramer framer;
  Collected out;
  feed(framer, "dwm> ", 1.0, out);
  EXPECT_TRUE(out.lines.empty());
  EXPECT_EQ(framer.pending(), "dwm> ");
  feed(framer, "les\r\nPOS,1", 2.0, out);
  feed(framer, ",2,3,4\r\n", 3.0, out);
  ASSERT_EQ(out.lines.size(), 2u);
  EXPECT_EQ(out.lines[0], "dwm> les");
  EXPECT_EQ(out.stamps[0], 1.0);
  EXPECT_EQ(out.lines[1], "POS,1,2,3,4");
  EXPECT_EQ(out.stamps[1], 2.0);
  EXPECT_EQ(framer.counters().bytes, 23u);
}

TEST(LineFramer, DiscardsOverlongLinesAndResynchronises) {
  LineFramer framer(16);
  Collected out;
  feed(framer, std::string(10, 'x'), 1.0, out);
  feed(framer, std::string(10, 'y'), 1.0, out);  // now 20 > 16 bytes without an end
  EXPECT_EQ(framer.pending(), "");
  feed(framer, std::string(100, 'z') + "\nok\n", 1.0, out);
  feed(framer, std::string(40, 'w') + "\nfine\n", 1.0, out);  // over-long within a chunk
  EXPECT_EQ(out.lines, (std::vector<std::string>{"ok", "fine"}));
  EXPECT_EQ(framer.counters().overflows, 2u);
}

TEST(LineFramer, ResetDropsPartialLine) {
  LineFramer framer;
  Collected out;
  feed(framer, "1151[5.00,8.0", 1.0, out);
  framer.reset();
  feed(framer, "POS,1,2,3,4\n", 2.0, out);
  ASSERT_EQ(out.lines.size(), 1u);
  EXPECT_EQ(out.lines[0], "POS,1,2,3,4");
}

TEST(LineFramer, ByteByByteEqualsWhole) {
  const std::string wire = "first line\r\nsecond\rthird\n";
  LineFramer framer;
  Collected out;
  for (std::size_t i = 0; i < wire.size(); ++i) {
    framer.feed(wire.data() + i, 1, static_cast<double>(i), out.sink());
  }
  EXPECT_EQ(out.lines, (std::vector<std::string>{"first line", "second", "third"}));
  EXPECT_EQ(out.stamps, (std::vector<double>{0.0, 12.0, 19.0}));
}

}  // namespace
}  // namespace radio_follow::drivers
