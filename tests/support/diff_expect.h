// expect_same_diff: two field diffs (history.h FieldChange lists) compared line by line, so a mismatch names the
// line and the field instead of printing two whole vectors. Used by the journal and document tests.
#pragma once

#include <vector>

#include <gtest/gtest.h>

#include "core/field_change.h"

namespace meshedit::testing {

inline void expect_same_diff(const std::vector<FieldChange>& got, const std::vector<FieldChange>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].element, want[i].element) << i;
    EXPECT_EQ(got[i].field, want[i].field) << i;
    EXPECT_EQ(got[i].before, want[i].before) << i;
    EXPECT_EQ(got[i].after, want[i].after) << i;
  }
}

}  // namespace meshedit::testing
