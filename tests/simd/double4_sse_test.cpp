// sse::Double4: the Double4 of builds with SSE2 but no AVX (RAYLAB_ARCH=x86-64, and programs that
// use the installed headers without -mavx). tests/CMakeLists.txt compiles this file with
// -march=x86-64, so that it is the implementation selected here; like the others it must widen
// exactly and round back as a scalar cast does, so that the triangle test keeps its bits. (The
// inline functions this file shares with the other test files are then compiled for two ISAs;
// the linker keeps one copy, and both run on the machines that run the tests.)

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <type_traits>

#include "raylab/core/rng.h"
#include "raylab/simd/double4.h"
#include "simd_test_util.h"

namespace raylab {
namespace {

using namespace test;  // simd_test_util.h
using Lanes = std::array<float, 4>;

Lanes lanes(simd::Float4 f) {
  Lanes out;
  f.store(out.data());
  return out;
}

TEST(Double4Sse, SelectedWithoutAvx) {
#if defined(__AVX__) || defined(RAYLAB_SIMD_SCALAR)
  GTEST_SKIP() << "this file was compiled with AVX or the scalar fallback";
#else
  static_assert(std::is_same_v<simd::Double4, simd::sse::Double4>);
#endif
}

// The triangle test's edge function a * b - c * d, exact in double and rounded once to float,
// and the round trip float -> double -> float, on special values, arbitrary bit patterns and
// products that overflow, underflow and cancel.
TEST(Double4Sse, EqualsScalarCode) {
  Pcg32 rng(14, 4);
  const auto& special = special_values();
  for (int iter = 0; iter < 30000 && !HasFailure(); ++iter) {
    Lanes a, b, c, d;
    for (int i = 0; i < 4; ++i) {
      a[i] = random_value(rng), b[i] = random_value(rng), c[i] = random_value(rng), d[i] = random_value(rng);
      if (iter % 3 == 1) c[i] = a[i], d[i] = std::nextafter(b[i], 0.f);  // cancellation
    }
    if (iter < int(special.size())) a[0] = special[std::size_t(iter)], d[3] = special[std::size_t(iter)];
    using D = simd::Double4;
    const D da = D::from(simd::Float4::load(a.data())), db = D::from(simd::Float4::load(b.data()));
    const D dc = D::from(simd::Float4::load(c.data())), dd = D::from(simd::Float4::load(d.data()));
    const Lanes edge = lanes((da * db - dc * dd).to_float()), back = lanes(da.to_float());
    for (int i = 0; i < 4; ++i) {
      const float expected = static_cast<float>(double(a[i]) * double(b[i]) - double(c[i]) * double(d[i]));
      EXPECT_TRUE(same_arith(edge[i], expected)) << a[i] << " * " << b[i] << " - " << c[i] << " * " << d[i];
      // A signaling NaN comes back quiet; everything else bit for bit.
      if (!std::isnan(a[i])) {
        EXPECT_EQ(bits(back[i]), bits(a[i])) << a[i];
      }
    }
  }
}

}  // namespace
}  // namespace raylab
