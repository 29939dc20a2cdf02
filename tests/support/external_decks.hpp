// The decks written by others live beside the repository (CLINCH_SHARED_DIR/external-decks), not
// in it: a test that reads them skips in a clone with nothing beside it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#define CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS()                                                  \
  do {                                                                                        \
    if (!std::filesystem::is_directory(std::string(CLINCH_SHARED_DIR) + "/external-decks")) { \
      GTEST_SKIP() << "no external decks beside the repository";                             \
    }                                                                                         \
  } while (false)
