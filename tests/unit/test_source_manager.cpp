// The file table (parser/source_manager.hpp): a file read from disk gives up its contents after
// parsing and reads them back when a diagnostic shows one of its lines; a file that changed size
// in between shows no line rather than a wrong one; in-memory buffers are never released.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "parser/source_manager.hpp"

namespace clinch {
namespace {

class TemporaryDeck {
 public:
  explicit TemporaryDeck(const std::string& text)
      : path_((std::filesystem::temp_directory_path() /
               ("clinch-source-" + std::to_string(getpid()) + ".inp"))
                  .string()) {
    write(text);
  }
  ~TemporaryDeck() { std::filesystem::remove(path_); }
  void write(const std::string& text) const { std::ofstream(path_, std::ios::binary) << text; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Loads the deck and releases its text, as read_deck_file does once parsing is over.
std::optional<std::uint32_t> load_and_release(const TemporaryDeck& deck, SourceManager& sources) {
  std::string error;
  const std::optional<std::uint32_t> index = sources.load(deck.path(), {}, &error);
  EXPECT_TRUE(index) << error;
  sources.release_texts();
  return index;
}

TEST(SourceManager, ReleasedFileIsReadBackForItsLines) {
  const TemporaryDeck deck("*NODE\n1, 0., 0., 0.\r\n2, 1., 0., 0.\n");
  SourceManager sources;
  const std::optional<std::uint32_t> index = load_and_release(deck, sources);
  ASSERT_TRUE(index);
  EXPECT_TRUE(sources.file(*index).text.empty());                 // the memory is gone
  EXPECT_EQ(sources.line_text({*index, 2, 1}), "1, 0., 0., 0.");  // without the CR
  EXPECT_EQ(sources.line_text({*index, 3, 1}), "2, 1., 0., 0.");
  EXPECT_EQ(sources.text(*index).size(), 35u);
}

TEST(SourceManager, FileThatChangedSizeShowsNoLine) {
  const TemporaryDeck deck("*NODE\n1, 0., 0., 0.\n");
  SourceManager sources;
  const std::optional<std::uint32_t> index = load_and_release(deck, sources);
  ASSERT_TRUE(index);
  deck.write("*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n");  // edited while the run went on
  EXPECT_EQ(sources.line_text({*index, 2, 1}), "");
  EXPECT_EQ(sources.text(*index), "");
}

TEST(SourceManager, BuffersAreKept) {
  SourceManager sources;
  const std::uint32_t index = sources.add_buffer("mem.inp", "*NODE\n1, 0., 0., 0.\n");
  sources.release_texts();
  EXPECT_EQ(sources.line_text({index, 2, 1}), "1, 0., 0., 0.");
}

}  // namespace
}  // namespace clinch
