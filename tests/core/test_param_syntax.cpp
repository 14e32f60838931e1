// Numeric parameter values are plain decimals (docs/reliability.md); strtod alone also took hex
// ("trace.rays=0x4"), "inf", and leading spaces.
#include <gtest/gtest.h>

#include "core/param.h"

TEST(ParamSyntax, OnlyPlainDecimalsAreNumbers) {
  Param count = Param::integer("rays", "rays per side", 2, 1, 16);
  Param bias = Param::real("bias", "depth bias", 0.01, 0, 1);
  for (const char* bad : {"0x4", "0X4", " 4", "4 ", "inf", "nan", "1e", "4e+", ".", "+", "-", "", "4,0", "1_0"}) {
    EXPECT_NE(count.set(bad), "") << "'" << bad << "' accepted";
    EXPECT_NE(bias.set(bad), "") << "'" << bad << "' accepted";
  }
  EXPECT_EQ(count.value, 2);
  for (const char* good : {"4", "+4", "4.0", "4.", "4e0", "0.4e1", "40e-1"}) {
    EXPECT_EQ(count.set(good), "") << good;
    EXPECT_EQ(count.value, 4) << good;
  }
  EXPECT_EQ(bias.set(".5"), "");
  EXPECT_DOUBLE_EQ(bias.value, 0.5);
  EXPECT_EQ(bias.set("5E-1"), "");
  EXPECT_NE(count.set("4.5"), "");  // still an integer parameter
}
