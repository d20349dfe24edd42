// Memory at rest, measured the same way for every contender: the growth of the resident set of a forked
// child over `work`, with freed heap pages handed back (malloc_trim) before both readings. The child
// leaves the parent's heap and timings untouched.
#pragma once

#include <functional>

namespace meshedit::bench {

// Runs `prepare`, then reads the child's RSS, runs `work`, reads it again; returns the difference in
// bytes, or -1 if the child failed (threw, crashed or could not be started).
long long rss_growth_in_child(const std::function<void()>& prepare, const std::function<void()>& work);

}  // namespace meshedit::bench
