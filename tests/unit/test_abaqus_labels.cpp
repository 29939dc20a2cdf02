// The two namings of history columns (src/output/abaqus_labels.hpp, output-variables.md §1.1):
// Abaqus's letters for rotational components against clinch's component numbers, the meanings
// and quantities the report and the study read from a name.
#include <gtest/gtest.h>

#include "src/output/abaqus_labels.hpp"

namespace clinch {
namespace {

TEST(AbaqusLabels, RotationalComponentsBothWays) {
  // alias n = component n + 3, for every pair of output-variables.md §1.1.
  const std::pair<const char*, const char*> pairs[] = {
      {"CTM1", "CTF4"},     {"CTM3", "CTF6"},   {"CEM2", "CEF5"},   {"CVM1", "CVF4"},
      {"CSM1", "CSF4"},     {"CRM3", "CRF6"},   {"CCM1", "CCF4"},   {"CNM2", "CNF5"},
      {"CUR1", "CU4"},      {"CUR3", "CU6"},    {"CCUR1", "CCU4"},  {"CPR2", "CP5"},
      {"CURE1", "CUE4"},    {"CURP3", "CUP6"},  {"CALPHAM1", "CALPHAF4"},
      {"CDMGR2", "CDMG5"},  {"CDIFR1", "CDIF4"}, {"CDIMR3", "CDIM6"}, {"CDIPR1", "CDIP4"},
      {"CVR1", "CV4"},      {"CAR2", "CA5"}};
  for (const auto& [abaqus, clinch_name] : pairs) {
    EXPECT_EQ(canonical_label(abaqus), clinch_name);
    EXPECT_EQ(abaqus_label(clinch_name), abaqus);
  }
}

TEST(AbaqusLabels, OtherNamesUnchanged) {
  for (const char* name : {"CTF1", "CTF3", "CU2", "CDMG", "CUPEQ", "CASU4", "CSLST5", "U1", "UR2",
                           "RM3", "S11", "CDERF-normal", "CUR4", "CTM", "step"}) {
    EXPECT_EQ(abaqus_label(canonical_label(name)), name) << name;
  }
  EXPECT_EQ(canonical_label("CUR4"), "CUR4");  // no fourth rotational axis
  EXPECT_EQ(abaqus_label("CASU4"), "CASU4");   // no Abaqus letter
}

TEST(AbaqusLabels, ColumnNamesKeepWhereTheyAre) {
  EXPECT_EQ(canonical_column_name("CTM1@Part-1-1.12"), "CTF4@Part-1-1.12");
  EXPECT_EQ(abaqus_column_name("CU6@7"), "CUR3@7");
  EXPECT_EQ(abaqus_column_name("CTF4@Weld, left"), "CTM1@Weld, left");
  EXPECT_EQ(column_name_in("CTF4@7", LabelStyle::Clinch), "CTF4@7");
  EXPECT_EQ(column_name_in("CTF4@7", LabelStyle::Abaqus), "CTM1@7");
  EXPECT_EQ(canonical_variable("ctm"), "CTF");
  EXPECT_EQ(canonical_variable("CUR"), "CU");
  EXPECT_EQ(canonical_variable("CSF"), "CSF");
  EXPECT_EQ(canonical_variable("UR"), "U");
  EXPECT_EQ(canonical_variable("RM"), "RF");
}

TEST(AbaqusLabels, MeaningsAndQuantities) {
  EXPECT_EQ(label_meaning("CTF1"), "total force in direction 1");
  EXPECT_EQ(label_meaning("CTF4"), "total moment about axis 1");
  EXPECT_EQ(label_meaning("CTM1"), "total moment about axis 1");
  EXPECT_EQ(label_meaning("CU6"), "relative rotation about axis 3");
  EXPECT_EQ(label_meaning("UR2"), "rotation about axis 2");
  EXPECT_EQ(label_meaning("CDMG"), "overall damage");
  EXPECT_EQ(label_meaning("CDERF-normal"), "derived force normal");
  EXPECT_EQ(column_quantity("CTF2@1"), Quantity::Force);
  EXPECT_EQ(column_quantity("CTM2@1"), Quantity::Moment);
  EXPECT_EQ(column_quantity("RM1@3"), Quantity::Moment);
  EXPECT_EQ(column_quantity("CUR1@1"), Quantity::Rotation);
  EXPECT_EQ(column_quantity("U3@3"), Quantity::Displacement);
  EXPECT_EQ(column_quantity("CDIF@1"), Quantity::Ratio);
  EXPECT_EQ(column_quantity("CSLST1@1"), Quantity::Status);
  EXPECT_EQ(column_quantity("V@1"), Quantity::Rate);
  EXPECT_EQ(column_quantity("VR2@1"), Quantity::Rate);
  EXPECT_EQ(column_quantity("XYZ@1"), Quantity::Other);
  const ColumnDescription d = describe_column("CRM1@Part-1-1.7");
  EXPECT_EQ(d.variable, "CRF");
  EXPECT_EQ(d.component, 4);
  EXPECT_EQ(d.where, "Part-1-1.7");
  EXPECT_EQ(d.abaqus_name, "CRM1@Part-1-1.7");
}

}  // namespace
}  // namespace clinch
