// Comparing returned values item by item: see value_compare.h for the contract and the messages' words.
#include "exercise/value_compare.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

using Kind = ExerciseValue::Kind;

// A point, or a list of 2 or 3 numbers read as one (z = 0 when left out).
bool as_point(const ExerciseValue& v, glm::dvec3& out) {
  if (v.kind == Kind::Point) {
    out = v.point;
    return true;
  }
  if (v.kind != Kind::List || v.items.size() < 2 || v.items.size() > 3) return false;
  glm::dvec3 p(0.0);
  for (size_t i = 0; i < v.items.size(); ++i) {
    if (v.items[i].kind != Kind::Number) return false;
    p[static_cast<glm::length_t>(i)] = v.items[i].number;
  }
  out = p;
  return true;
}

// The kind every item of the list is (Other when they are of several kinds, or none).
Kind items_kind(const ExerciseValue& list) {
  Kind kind = list.items.empty() ? Kind::Other : list.items.front().kind;
  for (const ExerciseValue& v : list.items) kind = v.kind == kind ? kind : Kind::Other;
  return kind;
}

// "3 points", "1 number", "2 lists", "4 values": how many items the list has, in the word for its items.
std::string count_of(const ExerciseValue& list) {
  const size_t n = list.items.size();
  const MessageParts count = {{"count", std::to_string(n)}};
  switch (items_kind(list)) {
    case Kind::Point: return tr_format(n == 1 ? "{count} point" : "{count} points", count);
    case Kind::Number: return tr_format(n == 1 ? "{count} number" : "{count} numbers", count);
    case Kind::List: return tr_format(n == 1 ? "{count} list" : "{count} lists", count);
    default: return tr_format(n == 1 ? "{count} value" : "{count} values", count);
  }
}

// "point 3 of 5": item i (from 0) of a list of m, named by the word for the reference's item (item_word).
std::string item_place(const ExerciseValue& item, size_t i, size_t m) {
  const MessageParts parts = {{"number", std::to_string(i + 1)}, {"count", std::to_string(m)}};
  switch (item.kind) {
    case Kind::Number: return tr_format("number {number} of {count}", parts);
    case Kind::Point: return tr_format("point {number} of {count}", parts);
    case Kind::List: return tr_format("list {number} of {count}", parts);
    default: return tr_format("value {number} of {count}", parts);
  }
}

class Comparer {
 public:
  Comparer(double tolerance, size_t max_messages, ValueComparison& out)
      : tolerance_(tolerance), max_(max_messages), out_(out) {}

  // `where` is "" for the returned value itself, else "point 3 of 5" (or "list 2 of 3, point 1 of 4").
  void compare(const ExerciseValue& mine, const ExerciseValue& reference, const std::string& where) {
    if (mine.kind != reference.kind) out_.identical = false;
    glm::dvec3 a, b;
    if (mine.kind == Kind::Number && reference.kind == Kind::Number) {
      const double d = std::abs(mine.number - reference.number);
      if (!(d <= tolerance_)) {
        differs(where, format_number(mine.number), format_number(reference.number), d);
      } else {
        agree(d, std::memcmp(&mine.number, &reference.number, sizeof(double)) == 0);
      }
      return;
    }
    if ((mine.kind == Kind::Point || reference.kind == Kind::Point) && as_point(mine, a) && as_point(reference, b)) {
      const double d = glm::distance(a, b);
      if (!(d <= tolerance_)) differs(where, format_position(a), format_position(b), d);
      else agree(d, mine.kind == reference.kind && std::memcmp(&a, &b, sizeof(a)) == 0);
      return;
    }
    if (mine.kind == Kind::List && reference.kind == Kind::List) return compare_lists(mine, reference, where);
    if (mine.kind == Kind::Nil && reference.kind == Kind::Nil) return;
    const MessageParts parts = {{"where", where}, {"mine", describe(mine)}, {"reference", describe(reference)}};
    if (where.empty()) {
      add(tr_format("yours returned {mine}, the reference {reference}", parts));
    } else {
      add(tr_format("{where} differs: yours is {mine}, the reference's {reference}", parts));
    }
  }

 private:
  void compare_lists(const ExerciseValue& mine, const ExerciseValue& reference, const std::string& where) {
    const size_t n = mine.items.size(), m = reference.items.size();
    if (n != m) {
      out_.identical = false;
      // "the reference 3" when both lists hold the same kind of item, else "the reference 3 points".
      const bool same_kind = n > 0 && m > 0 && items_kind(mine) == items_kind(reference);
      const MessageParts parts = {
          {"where", where}, {"yours", count_of(mine)}, {"count", std::to_string(m)}, {"theirs", count_of(reference)}};
      if (where.empty()) {
        add(same_kind ? tr_format("yours returned {yours}, the reference {count}", parts)
                      : tr_format("yours returned {yours}, the reference {theirs}", parts));
      } else {
        add(same_kind ? tr_format("{where}: yours has {yours}, the reference's {count}", parts)
                      : tr_format("{where}: yours has {yours}, the reference's {theirs}", parts));
      }
    }
    for (size_t i = 0; i < std::min(n, m); ++i) {
      const std::string item = item_place(reference.items[i], i, m);
      compare(mine.items[i], reference.items[i],
              where.empty() ? item : tr_format("{where}, {item}", {{"where", where}, {"item", item}}));
    }
  }

  void differs(const std::string& where, const std::string& mine, const std::string& reference, double d) {
    out_.identical = false;
    const MessageParts parts = {
        {"where", where}, {"mine", mine}, {"reference", reference}, {"distance", format_number(d)}};
    if (where.empty()) {
      add(tr_format("yours returned {mine}, the reference {reference} ({distance} apart)", parts));
    } else {
      add(tr_format("{where} differs: yours {mine}, the reference's {reference}", parts));
    }
  }

  void agree(double d, bool bitwise) {
    out_.worst = std::max(out_.worst, d);
    out_.identical = out_.identical && bitwise;
  }

  void add(std::string message) {
    out_.equal = false;
    out_.identical = false;
    ++out_.total;
    if (out_.differences.size() < max_) out_.differences.push_back(std::move(message));
  }

  double tolerance_;
  size_t max_;
  ValueComparison& out_;
};

}  // namespace

ValueComparison compare_values(const ExerciseValue& mine, const ExerciseValue& reference, double tolerance,
                               size_t max_messages) {
  ValueComparison out;
  Comparer(tolerance, max_messages, out).compare(mine, reference, "");
  return out;
}

}  // namespace meshedit
