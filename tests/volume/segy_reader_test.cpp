// Every file of shared/data/segy read (or refused) as DATA.md describes, plus the formats, byte
// orders, sortings and irregular surveys the generator's writer makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "volume/volume_error.h"
#include "volume_test_support.h"

namespace cutaway::test {
namespace {

using volume::load_segy;
using volume::VolumeCube;
using volume::VolumeError;

/// Runs `load` and returns the VolumeError message ("" when nothing was thrown).
template <typename Load>
std::string refusal(Load&& load) {
    try {
        load();
    } catch (const VolumeError& error) {
        return error.what();
    }
    return "";
}

TEST(SegyReader, F3IsTheRealCropWithLineNumbersAndInterval) {
    const VolumeCube cube = load_segy(segy_file("f3.sgy"));
    EXPECT_EQ(cube.dims.inlines, 23);
    EXPECT_EQ(cube.dims.crosslines, 18);
    EXPECT_EQ(cube.dims.samples, 75);
    EXPECT_DOUBLE_EQ(cube.sample_interval_ms, 4.0);
    EXPECT_EQ(cube.format_name, "int16 (3)");
    EXPECT_FALSE(cube.little_endian);
    EXPECT_EQ(cube.sorting, volume::TraceSorting::inline_major);
    EXPECT_TRUE(cube.missing_traces.empty());
    EXPECT_EQ(cube.inline_numbers.front(), 111);
    EXPECT_EQ(cube.inline_numbers.back(), 133);
    EXPECT_EQ(cube.crossline_numbers.back() - cube.crossline_numbers.front(), 17);
    // Trace 5 of the file is inline 111, crossline 880; its sample 20 is the int16 262 (read raw
    // with segyio while writing this test).
    EXPECT_EQ(cube.at(0, 880 - cube.crossline_numbers.front(), 20), 262.0f);
}

TEST(SegyReader, LittleEndianAndIeeeCopiesOfF3HoldTheSameSamples) {
    const VolumeCube msb = load_segy(segy_file("f3.sgy"));
    const VolumeCube lsb = load_segy(segy_file("f3-lsb.sgy"));
    const VolumeCube ieee = load_segy(segy_file("Format5msb.sgy"));
    EXPECT_TRUE(lsb.little_endian);
    EXPECT_EQ(ieee.format_name, "IEEE float (5)");
    EXPECT_EQ(lsb.samples, msb.samples);
    EXPECT_EQ(lsb.inline_numbers, msb.inline_numbers);
    ASSERT_EQ(ieee.samples.size(), msb.samples.size());
    // Integers up to 2^15 are exact in IEEE single precision.
    EXPECT_EQ(ieee.samples, msb.samples);
}

TEST(SegyReader, SmallIsFiveByFiveIbmWithKnownValues) {
    const VolumeCube cube = load_segy(segy_file("small.sgy"));
    EXPECT_EQ(cube.format_name, "IBM float (1)");
    ASSERT_EQ(cube.dims.inlines, 5);
    ASSERT_EQ(cube.dims.crosslines, 5);
    ASSERT_EQ(cube.dims.samples, 50);
    // segyio's test cube: sample t of (inline il, crossline xl) = il + xl / 100 + t / 1e5; IBM to
    // IEEE conversion keeps 6-7 digits, hence 1e-5.
    for (int i = 0; i < 5; ++i)
        for (int x = 0; x < 5; ++x)
            for (int t : {0, 1, 49})
                EXPECT_NEAR(cube.at(i, x, t), cube.inline_numbers[std::size_t(i)] +
                                                  cube.crossline_numbers[std::size_t(x)] / 100.0 + t / 1e5, 1e-5);
}

TEST(SegyReader, TinyIsThreeByTwoByFour) {
    const VolumeCube cube = load_segy(segy_file("tiny.sgy"));
    EXPECT_EQ(cube.dims.inlines, 3);
    EXPECT_EQ(cube.dims.crosslines, 2);
    EXPECT_EQ(cube.dims.samples, 4);
    EXPECT_TRUE(cube.missing_traces.empty());
}

TEST(SegyReader, RefusesPreStackOneByOne) {
    const std::string message = refusal([] { load_segy(segy_file("1x1.sgy")); });
    EXPECT_NE(message.find("1x1.sgy"), std::string::npos) << message;
    EXPECT_NE(message.find("pre-stack"), std::string::npos) << message;
}

TEST(SegyReader, RefusesTruncatedBroken) {
    const std::string message = refusal([] { load_segy(segy_file("broken.sgy")); });
    EXPECT_NE(message.find("broken.sgy"), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(SegyReader, EveryFormatAndByteOrderRoundTrips) {
    const ScratchDir dir = unique_scratch("segy-formats");
    const generators::SeismicVolume volume = synthetic_volume(4, 5, 30);
    float peak = 0;
    for (float a : volume.amplitudes) peak = std::max(peak, std::abs(a));
    for (int format : {1, 2, 3, 5, 8})
        for (bool lsb : {false, true}) {
            SCOPED_TRACE("format " + std::to_string(format) + (lsb ? " LSB" : " MSB"));
            generators::SegyWriteOptions options;
            options.format = format;
            options.little_endian = lsb;
            const VolumeCube cube = write_and_load(dir, "cube.sgy", volume, options);
            EXPECT_EQ(cube.little_endian, lsb);
            ASSERT_EQ(cube.dims.count(), volume.amplitudes.size());
            EXPECT_EQ(cube.inline_numbers.front(), 1);
            EXPECT_DOUBLE_EQ(cube.sample_interval_ms, 4.0);
            // Integer formats store amplitude * 0.9 range / peak, rounded: compare normalised by
            // the peaks; rounding moves a sample by half a step of the integer grid and the peak by as much again,
            // so one step (int8: 1/114) bounds the error; float formats keep about 6 digits.
            float read_peak = 0;
            for (float a : cube.samples) read_peak = std::max(read_peak, std::abs(a));
            const double tolerance = format == 8 ? 1 / 114.3 : format == 3 ? 1 / 29490.0 : 1e-5;
            double worst = 0;
            for (std::size_t k = 0; k < cube.samples.size(); ++k)
                worst = std::max(worst, std::abs(double(cube.samples[k]) / read_peak - double(volume.amplitudes[k]) / peak));
            EXPECT_LE(worst, tolerance);
        }
}

TEST(SegyReader, CrosslineSortedReadsAsTheSameCube) {
    const ScratchDir dir = unique_scratch("segy-sorting");
    const generators::SeismicVolume volume = synthetic_volume(4, 6, 20);
    generators::SegyWriteOptions crossline;
    crossline.crossline_sorted = true;
    const VolumeCube by_inline = write_and_load(dir, "inline.sgy", volume);
    const VolumeCube by_crossline = write_and_load(dir, "crossline.sgy", volume, crossline);
    EXPECT_EQ(by_inline.sorting, volume::TraceSorting::inline_major);
    EXPECT_EQ(by_crossline.sorting, volume::TraceSorting::crossline_major);
    EXPECT_EQ(by_crossline.samples, by_inline.samples);
}

TEST(SegyReader, IrregularSurveyFillsMissingTracesWithTheNullValue) {
    const ScratchDir dir = unique_scratch("segy-irregular");
    const generators::SeismicVolume volume = synthetic_volume(5, 4, 10);
    generators::SegyWriteOptions options;
    options.missing_traces = {{1, 2}, {3, 0}};
    volume::SegyReadOptions read;
    read.null_value = -999;
    const VolumeCube cube = write_and_load(dir, "irregular.sgy", volume, options, read);
    ASSERT_EQ(cube.dims.inlines, 5);
    ASSERT_EQ(cube.dims.crosslines, 4);
    const std::vector<std::pair<int, int>> expected{{2, 3}, {4, 1}};  // numbers start at 1
    EXPECT_EQ(cube.missing_traces, expected);
    for (int t = 0; t < 10; ++t) {
        EXPECT_EQ(cube.at(1, 2, t), -999.0f);
        EXPECT_EQ(cube.at(3, 0, t), -999.0f);
        EXPECT_EQ(cube.at(2, 2, t), volume.amplitudes[volume.index(2, 2, t)]);
    }
    // The null value stays out of the value range used for the 256 levels.
    EXPECT_GT(volume::present_value_range(cube).min, -999.0f);
}

TEST(SegyReader, RefusesWrittenPreStack) {
    const ScratchDir dir = unique_scratch("segy-prestack");
    generators::SegyWriteOptions options;
    options.offsets = 3;
    const std::string message =
        refusal([&] { write_and_load(dir, "prestack.sgy", synthetic_volume(2, 2, 8), options); });
    EXPECT_NE(message.find("pre-stack"), std::string::npos) << message;
    EXPECT_NE(message.find("offsets 1 and 2"), std::string::npos) << message;
}

}  // namespace
}  // namespace cutaway::test
