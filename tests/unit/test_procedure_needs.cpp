// The merged needs of a model's laws (base/procedure_needs.hpp): the longest line search
// with its reason, and each note once however many laws share it.
#include <gtest/gtest.h>

#include "base/procedure_needs.hpp"

namespace clinch {
namespace {

TEST(ProcedureNeeds, MergeKeepsTheLongestLineSearchAndEachNoteOnce) {
  ProcedureNeeds merged;
  merged.merge({});
  EXPECT_EQ(merged.line_search_iterations, 0);
  EXPECT_TRUE(merged.notes.empty());

  merged.merge({5, "the step has friction", {"rate note"}});
  merged.merge({3, "a shorter one", {"rate note", "other note"}});
  merged.merge({5, "the step has friction", {"rate note"}});
  EXPECT_EQ(merged.line_search_iterations, 5);
  EXPECT_EQ(merged.line_search_reason, "the step has friction");
  EXPECT_EQ(merged.notes, (std::vector<std::string>{"rate note", "other note"}));
}

}  // namespace
}  // namespace clinch
