// The outputs of `clinch study`: the table printed on stdout, the settings CSV (one row per
// setting; what the work-precision plot and `clinch report --study` read) and the columns CSV
// (one row per setting and history column: every column's difference from the finest run, its
// estimated error and observed order).
#pragma once

#include <string>

#include "src/study/study_result.hpp"

namespace clinch {

std::string render_study_table(const StudyResult& result);

// Each returns false and sets `error` when the file cannot be written.
bool write_settings_csv(const StudyResult& result, const std::string& path, std::string* error);
bool write_columns_csv(const StudyResult& result, const std::string& path, std::string* error);

}  // namespace clinch
