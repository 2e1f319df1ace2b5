// CPU tier: what a headless sequence is made of, without rendering: frame ranges as a farm's
// jobs give them, the clock derived from the frame number (so a range poses frame f as the whole
// run does), video formats by extension and the partial names files are written under.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/headless/frame_sequence.h"
#include "app/video/video_encoder.h"

namespace npr {
namespace {

TEST(FrameRange, ParsesPairsAndSingleFrames) {
  Result<FrameRange> r = parseFrameRange("3-5", 12);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->first, 3);
  EXPECT_EQ(r->last, 5);
  EXPECT_EQ(r->count(), 3);
  Result<FrameRange> one = parseFrameRange("11", 12);
  ASSERT_TRUE(one) << one.error();
  EXPECT_EQ(one->first, 11);
  EXPECT_EQ(one->last, 11);
  Result<FrameRange> all = parseFrameRange("0-11", 12);
  ASSERT_TRUE(all);
  EXPECT_EQ(all->count(), 12);
}

TEST(FrameRange, RefusesWhatIsNotARangeOfTheSequence) {
  for (const char* bad : {"5-3", "0-12", "12", "-1", "-1-3", "3-", "x", "", "1-2-3", "3 -5", " 3", "+3", "3-5x"}) {
    Result<FrameRange> r = parseFrameRange(bad, 12);
    EXPECT_FALSE(r) << "'" << bad << "' was taken as " << (r ? r->first : -1) << "-" << (r ? r->last : -1);
  }
  // Past the end names the frames there are.
  EXPECT_NE(parseFrameRange("0-12", 12).error().find("frames 0..11"), std::string::npos);
}

TEST(SequenceTime, IsDerivedFromTheFrameNumberAndLoops) {
  // Frame 1000 at 30 frames a second over a 2-second loop: 33.333 s into the clock, 1.333 s into the loop.
  EXPECT_NEAR(sequenceTime(0.0, 1000, 30.0, 1.0, 2.0), std::fmod(1000.0 / 30.0, 2.0), 1e-12);
  EXPECT_NEAR(sequenceTime(0.5, 3, 10.0, 2.0, 4.0), 1.1, 1e-12);
  EXPECT_EQ(sequenceTime(1.0, 7, 30.0, 1.0, 0.0), 0.0);  // a still scene
  // The same frame the same time, however it is reached: no sum of steps to drift.
  double summed = 0.0;
  for (int f = 0; f < 1000; ++f) summed += 1.0 / 30.0;
  EXPECT_EQ(sequenceTime(0.0, 1000, 30.0, 1.0, 1e9), 1000.0 / 30.0);
  EXPECT_NE(summed, 1000.0 / 30.0);  // what summing would have given
}

TEST(VideoFormat, ByExtension) {
  EXPECT_EQ(*videoFormatOf("a/b.mp4"), VideoFormat::Mp4);
  EXPECT_EQ(*videoFormatOf("B.MP4"), VideoFormat::Mp4);
  EXPECT_EQ(*videoFormatOf("x.webm"), VideoFormat::WebM);
  EXPECT_EQ(*videoFormatOf("x.gif"), VideoFormat::Gif);
  for (const char* bad : {"x.avi", "x", "mp4", "x.mp4.part"}) EXPECT_FALSE(videoFormatOf(bad)) << bad;
  EXPECT_NE(videoFormatOf("x.avi").error().find(".mp4 (H.264), .webm (VP9) or .gif"), std::string::npos);
}

TEST(VideoFormat, PartialNamesAreHiddenBesideTheFileAndKeepTheExtension) {
  EXPECT_EQ(partialFileName("out/shot.mp4"), "out/.shot.partial.mp4");
  EXPECT_EQ(partialFileName("shot.gif"), ".shot.partial.gif");
}

}  // namespace
}  // namespace npr
