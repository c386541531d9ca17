// The vectorised row reads against the scalar sampler they replace. ctest runs this suite three
// times, once per compiled copy (PARAFLUID_SIMD=baseline, =avx2, and the widest the CPU has), so
// a copy that a compiler or a dispatch change breaks fails here by name.
#include "RowSampling.h"
#include "GridSampling.h"
#include "parafluid/common/SimdDispatch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using namespace parafluid::clouds;

const char* copyName()
{
  switch (parafluid::common::simdLevel())
  {
    case parafluid::common::SimdLevel::Avx512:
      return "AVX-512";
    case parafluid::common::SimdLevel::Avx2:
      return "AVX2";
    default:
      return "baseline";
  }
}

// A 13 x 9 x 7 array of a face-centred layout filled with noise, and points in and beyond it.
struct Fixture
{
  GridArray a, b;
  std::vector<double> x, y, z;
  explicit Fixture(int count)
  {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-3.0, 5.0);
    for (GridArray* g : { &a, &b })
    {
      g->dims = { 13, 9, 7 };
      g->offset = { 0.0, 0.5, 0.5 };
      g->values.resize(13 * 9 * 7);
      for (double& v : g->values)
        v = value(random);
    }
    // Most inside, some past every face (the reads clamp there, as the scalar sampler does).
    std::uniform_real_distribution<double> px(-1.5, 13.5), py(-1.5, 9.5), pz(-1.5, 7.5);
    for (int i = 0; i < count; ++i)
    {
      x.push_back(px(random));
      y.push_back(py(random));
      z.push_back(pz(random));
    }
  }
};

TEST(RowSampling, ReadsMatchTheScalarSampler)
{
  const int count = 1001; // not a multiple of any vector width: the tails run too
  const Fixture f(count);
  const detail::DirectSampler sampler(f.a);
  std::vector<double> plain(count), ranged(count), lo(count), hi(count), pairA(count), pairB(count), loB(count),
    hiB(count);
  detail::readRow(detail::RowLayout(f.a), f.a.values.data(), f.x.data(), f.y.data(), f.z.data(), count, ranged.data(),
                  lo.data(), hi.data());
  detail::readRow(detail::RowLayout(f.a), f.a.values.data(), f.x.data(), f.y.data(), f.z.data(), count, plain.data());
  detail::readRowPair(detail::RowLayout(f.a), f.a.values.data(), f.b.values.data(), f.x.data(), f.y.data(), f.z.data(),
                      count, pairA.data(), pairB.data(), loB.data(), hiB.data());
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { f.x[i], f.y[i], f.z[i] };
    double low, high, lowB, highB;
    const double expected = sampler.at(f.a.values.data(), p, &low, &high);
    const double expectedB = sampler.at(f.b.values.data(), p, &lowB, &highB);
    ASSERT_NEAR(plain[i], expected, 1e-12) << copyName() << " copy, point " << i;
    ASSERT_EQ(lo[i], low) << copyName() << " copy, point " << i;
    ASSERT_EQ(hi[i], high) << copyName() << " copy, point " << i;
    ASSERT_NEAR(ranged[i], expected, 1e-12) << copyName() << " copy, with range, point " << i;
    ASSERT_NEAR(pairA[i], expected, 1e-12) << copyName() << " copy, pair, point " << i;
    ASSERT_NEAR(pairB[i], expectedB, 1e-12) << copyName() << " copy, pair, point " << i;
    ASSERT_EQ(loB[i], lowB) << copyName() << " copy, pair, point " << i;
    ASSERT_EQ(hiB[i], highB) << copyName() << " copy, pair, point " << i;
  }
}

TEST(RowSampling, PairWithRangesOfTwoOtherArraysMatchesTheScalarSampler)
{
  // Reads of a and b, ranges of b and a (crossed, so a swapped pointer shows).
  const int count = 1001;
  const Fixture f(count);
  const detail::DirectSampler sampler(f.a);
  std::vector<double> outA(count), outB(count), loB(count), hiB(count), loA(count), hiA(count);
  detail::readRowPairRanged(detail::RowLayout(f.a), f.a.values.data(), f.b.values.data(), f.b.values.data(),
                            f.a.values.data(), f.x.data(), f.y.data(), f.z.data(), count, outA.data(), outB.data(),
                            loB.data(), hiB.data(), loA.data(), hiA.data());
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { f.x[i], f.y[i], f.z[i] };
    double lowA, highA, lowB, highB;
    const double expectedA = sampler.at(f.a.values.data(), p, &lowA, &highA);
    const double expectedB = sampler.at(f.b.values.data(), p, &lowB, &highB);
    ASSERT_NEAR(outA[i], expectedA, 1e-12) << copyName() << " copy, point " << i;
    ASSERT_NEAR(outB[i], expectedB, 1e-12) << copyName() << " copy, point " << i;
    ASSERT_EQ(loB[i], lowB) << copyName() << " copy, point " << i;
    ASSERT_EQ(hiB[i], highB) << copyName() << " copy, point " << i;
    ASSERT_EQ(loA[i], lowA) << copyName() << " copy, point " << i;
    ASSERT_EQ(hiA[i], highA) << copyName() << " copy, point " << i;
  }
}

TEST(RowSampling, RowsThatMoveAlikeMatchTheScalarSampler)
{
  // Rows of samples traced as a smooth flow traces them: runs of neighbouring points whose
  // corners lie side by side (read by vector loads), broken where a trace crosses a cell face
  // against its neighbours, and rows pushed past the array's ends (clamped, where runs repeat
  // corners). Longer than a block, so the blocks' seams are crossed too.
  GridArray a, b;
  for (GridArray* g : { &a, &b })
  {
    g->dims = { 600, 5, 4 };
    g->offset = { 0.0, 0.5, 0.5 };
    g->values.resize(600 * 5 * 4);
  }
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-3.0, 5.0);
  for (std::size_t c = 0; c < a.values.size(); ++c)
  {
    a.values[c] = value(random);
    b.values[c] = value(random);
  }
  const detail::DirectSampler sampler(a);
  const int count = 600;
  std::vector<double> x(count), y(count), z(count);
  std::vector<double> outA(count), outB(count), lo(count), hi(count), loB(count), hiB(count), loA(count), hiA(count);
  int rowsChecked = 0;
  for (double shift : { 0.0, 0.35, -0.8, 2.6 })
  {
    for (double amplitude : { 0.0, 0.45, 1.3 })
    {
      for (int j = -1; j <= 5; j += 2)
      {
        for (int i = 0; i < count; ++i)
        {
          const double wave = amplitude * std::sin(0.07 * i + j);
          x[i] = i + shift + wave;
          y[i] = j + 0.5 - 0.6 * wave + 0.3 * shift;
          z[i] = 1.5 + 0.4 * wave - shift;
        }
        const detail::RowLayout layout(a);
        detail::readRow(layout, a.values.data(), x.data(), y.data(), z.data(), count, outA.data(), lo.data(),
                        hi.data());
        detail::readRowPair(layout, a.values.data(), b.values.data(), x.data(), y.data(), z.data(), count, loA.data(),
                            outB.data(), loB.data(), hiB.data());
        for (int i = 0; i < count; ++i)
        {
          const double p[3] = { x[i], y[i], z[i] };
          double low, high, lowB, highB;
          const double expected = sampler.at(a.values.data(), p, &low, &high);
          const double expectedB = sampler.at(b.values.data(), p, &lowB, &highB);
          ASSERT_NEAR(outA[i], expected, 1e-12) << copyName() << " copy, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(lo[i], low) << copyName() << " copy, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(hi[i], high) << copyName() << " copy, row " << rowsChecked << ", point " << i;
          ASSERT_NEAR(loA[i], expected, 1e-12) << copyName() << " copy, pair, row " << rowsChecked << ", point " << i;
          ASSERT_NEAR(outB[i], expectedB, 1e-12) << copyName() << " copy, pair, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(loB[i], lowB) << copyName() << " copy, pair, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(hiB[i], highB) << copyName() << " copy, pair, row " << rowsChecked << ", point " << i;
        }
        detail::readRowPairRanged(layout, b.values.data(), a.values.data(), a.values.data(), b.values.data(), x.data(),
                                  y.data(), z.data(), count, outB.data(), outA.data(), loA.data(), hiA.data(),
                                  loB.data(), hiB.data());
        for (int i = 0; i < count; ++i)
        {
          const double p[3] = { x[i], y[i], z[i] };
          double lowA, highA, lowB, highB;
          const double expectedA = sampler.at(a.values.data(), p, &lowA, &highA);
          const double expectedB = sampler.at(b.values.data(), p, &lowB, &highB);
          ASSERT_NEAR(outA[i], expectedA, 1e-12)
            << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
          ASSERT_NEAR(outB[i], expectedB, 1e-12)
            << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(loA[i], lowA) << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(hiA[i], highA) << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(loB[i], lowB) << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
          ASSERT_EQ(hiB[i], highB) << copyName() << " copy, ranged, row " << rowsChecked << ", point " << i;
        }
        ++rowsChecked;
      }
    }
  }
  EXPECT_EQ(rowsChecked, 48);
}

TEST(RowSampling, ScatterIsTheTransposeOfTheRead)
{
  // The weights a row scatters are those the scalar sampler's forCorners gives, summed.
  const int count = 1001;
  const Fixture f(count);
  const detail::DirectSampler sampler(f.a);
  std::vector<double> expected(f.a.values.size(), 0.0), scattered(f.a.values.size(), 0.0);
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { f.x[i], f.y[i], f.z[i] };
    sampler.forCorners(p, [&](std::size_t index, double weight) { expected[index] += weight; });
  }
  std::vector<int> base(count);
  std::vector<double> fx(count), fy(count), fz(count);
  detail::scatterRow(detail::RowLayout(f.a), f.x.data(), f.y.data(), f.z.data(), count, base.data(), fx.data(),
                     fy.data(), fz.data(), scattered.data());
  double total = 0.0;
  for (std::size_t c = 0; c < expected.size(); ++c)
  {
    ASSERT_NEAR(scattered[c], expected[c], 1e-12) << copyName() << " copy, sample " << c;
    total += scattered[c];
  }
  EXPECT_NEAR(total, count, 1e-9) << "each point's weights sum to one";
}

TEST(RowSampling, MeanOfShiftedRowsIsTheMeanOfItsTerms)
{
  std::vector<std::vector<double>> rows(4, std::vector<double>(40));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (auto& r : rows)
    for (double& v : r)
      v = value(random);
  const double* pointers[4] = { rows[0].data(), rows[1].data(), rows[2].data(), rows[3].data() };
  const int shifts[2] = { 0, 1 };
  for (int rowCount : { 1, 2, 4 })
  {
    for (int shiftCount : { 1, 2 })
    {
      std::vector<double> out(40, -99.0);
      detail::meanOfShiftedRows(pointers, rowCount, shifts, shiftCount, 2, 36, out.data());
      for (int i = 0; i < 40; ++i)
      {
        if (i < 2 || i > 36)
        {
          EXPECT_EQ(out[i], -99.0) << "outside [first, last] untouched";
          continue;
        }
        double sum = 0.0;
        for (int r = 0; r < rowCount; ++r)
          for (int s = 0; s < shiftCount; ++s)
            sum += rows[r][i + shifts[s]];
        EXPECT_NEAR(out[i], sum / (rowCount * shiftCount), 1e-15)
          << copyName() << " copy, " << rowCount << " rows, " << shiftCount << " shifts, i = " << i;
      }
    }
  }
}
} // namespace
