// The file table and the scanning of its files (parser/source_manager.hpp, parser/file_scan.hpp):
// a file on disk is streamed through a window and read back when a diagnostic shows one of its
// lines; a file that changed size in between shows no line rather than a wrong one, and one that
// changed while it was read is an error, and one whose read fails part-way is an I/O error (not a
// diagnostic); in-memory buffers are kept; the first pass records where
// each block's keyword line is, which bounds the block's data lines.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "parser/deck_reader.hpp"
#include "parser/file_scan.hpp"
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

std::optional<std::uint32_t> load(const TemporaryDeck& deck, SourceManager& sources) {
  std::string error;
  const std::optional<std::uint32_t> index = sources.load(deck.path(), {}, &error);
  EXPECT_TRUE(index) << error;
  return index;
}

// Loads the deck and releases any text read back, as read_deck_file does once parsing is over.
std::optional<std::uint32_t> load_and_release(const TemporaryDeck& deck, SourceManager& sources) {
  const std::optional<std::uint32_t> index = load(deck, sources);
  sources.release_texts();
  return index;
}

TEST(SourceManager, FileOnDiskIsReadBackForItsLines) {
  const TemporaryDeck deck("*NODE\n1, 0., 0., 0.\r\n2, 1., 0., 0.\n");
  SourceManager sources;
  const std::optional<std::uint32_t> index = load_and_release(deck, sources);
  ASSERT_TRUE(index);
  EXPECT_TRUE(sources.file(*index).text.empty());                 // not held
  EXPECT_EQ(sources.line_text({*index, 2, 1}), "1, 0., 0., 0.");  // without the CR
  EXPECT_EQ(sources.line_text({*index, 3, 1}), "2, 1., 0., 0.");
  EXPECT_EQ(sources.text(*index).size(), 35u);
  sources.release_texts();
  EXPECT_TRUE(sources.file(*index).text.empty());  // given back again
}

struct ScannedLine {
  LineScanner::Kind kind;
  std::string text;
  std::uint32_t line;
  bool operator==(const ScannedLine&) const = default;
};

std::vector<ScannedLine> scan_all(LineScanner& scanner) {
  std::vector<ScannedLine> lines;
  for (auto k = scanner.next(); k != LineScanner::Kind::End; k = scanner.next()) {
    lines.push_back({k, std::string(scanner.text()), scanner.loc().line});
  }
  return lines;
}

// A window of 8 bytes refills on almost every line and must grow for the 300-byte line; the lines,
// their numbers and the line-level diagnostics (E0107, W0101) are those of the text in memory.
TEST(FileScan, WindowedFileScansLikeTheTextInMemory) {
  const std::string text = "*NODE\r\n1, 0.\n\n** comment\n" + std::string(300, 'x') +
                           "\n2, \x01\n*ELEMENT, TYPE=CONN3D2\n1, 1, 2";
  const TemporaryDeck deck(text);
  DiagnosticSink memory_sink, file_sink;
  LineScanner in_memory(text, 0, memory_sink);
  LineScanner windowed(std::make_unique<FileWindow>(deck.path(), 8), 0, file_sink);
  const std::vector<ScannedLine> expected = scan_all(in_memory);
  ASSERT_EQ(expected.size(), 8u);
  EXPECT_EQ(expected[0].text, "*NODE");
  EXPECT_EQ(expected[4].text.size(), 300u);
  EXPECT_EQ(expected[7].text, "1, 1, 2");
  EXPECT_EQ(scan_all(windowed), expected);
  EXPECT_EQ(windowed.bytes_read(), text.size());
  ASSERT_EQ(file_sink.diagnostics().size(), memory_sink.diagnostics().size());
  ASSERT_EQ(file_sink.diagnostics().size(), 2u);  // the long line and the control character
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(file_sink.diagnostics()[i].loc, memory_sink.diagnostics()[i].loc);
    EXPECT_EQ(file_sink.diagnostics()[i].message, memory_sink.diagnostics()[i].message);
  }
}

// Every deck of the repository (examples, verification cases, bad decks) read through a window of
// 7 bytes, so that nearly every line straddles a refill: the same lines and line-level
// diagnostics as the text in memory.
TEST(FileScan, EveryRepositoryDeckScansLikeItsTextThroughATinyWindow) {
  int decks = 0;
  for (const char* folder : {"decks", "tests/diagnostics"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             std::string(CLINCH_SOURCE_DIR) + "/" + folder)) {
      if (entry.path().extension() != ".inp") continue;
      std::ifstream file(entry.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(file)),
                             std::istreambuf_iterator<char>());
      DiagnosticSink memory_sink, file_sink;
      LineScanner in_memory(text, 0, memory_sink);
      LineScanner windowed(std::make_unique<FileWindow>(entry.path().string(), 7), 0, file_sink);
      EXPECT_EQ(scan_all(windowed), scan_all(in_memory)) << entry.path();
      EXPECT_EQ(windowed.bytes_read(), text.size()) << entry.path();
      EXPECT_EQ(file_sink.diagnostics().size(), memory_sink.diagnostics().size()) << entry.path();
      ++decks;
    }
  }
  EXPECT_GT(decks, 100);
}

// A file that grew between being opened and being read is not the deck that was checked.
TEST(FileScan, FileThatChangedBeforeItWasReadIsAnError) {
  const TemporaryDeck deck("*NODE\n1, 0., 0., 0.\n");
  SourceManager sources;
  const std::optional<std::uint32_t> index = load(deck, sources);
  ASSERT_TRUE(index);
  deck.write("*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n");
  DiagnosticSink sink;
  LineScanner scanner = scan_file(sources, *index, sink);
  EXPECT_EQ(scan_all(scanner).size(), 3u);
  check_read_whole(sources, scanner, *index, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::file_not_found);
  EXPECT_EQ(sink.diagnostics()[0].loc, (SourceLoc{*index, 3, 1}));
  EXPECT_NE(sink.diagnostics()[0].message.find("changed while it was read (20 bytes when opened, "
                                               "34 read)"),
            std::string::npos)
      << sink.diagnostics()[0].message;
}

TEST(FileScan, FileRemovedBeforeItWasReadIsAnError) {
  SourceManager sources;
  std::optional<std::uint32_t> index;
  {
    const TemporaryDeck deck("*NODE\n");
    index = load(deck, sources);
  }
  ASSERT_TRUE(index);
  DiagnosticSink sink;
  LineScanner scanner = scan_file(sources, *index, sink);
  EXPECT_EQ(scanner.next(), LineScanner::Kind::End);
  check_read_whole(sources, scanner, *index, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_NE(sink.diagnostics()[0].message.find("No such file or directory"), std::string::npos)
      << sink.diagnostics()[0].message;
}

// A stream that gives the first `good` bytes of `text`, then fails every read with EIO, as a
// disk with a bad sector does part-way through a file.
struct FailingStream {
  std::string text;
  std::size_t good = 0;
  std::size_t offset = 0;
};

std::FILE* open_failing_stream(FailingStream& stream) {
  cookie_io_functions_t functions{};
  functions.read = [](void* cookie, char* buffer, std::size_t size) -> ssize_t {
    auto& s = *static_cast<FailingStream*>(cookie);
    if (s.offset >= s.good) {
      errno = EIO;
      return -1;
    }
    const std::size_t n = std::min(size, s.good - s.offset);
    std::memcpy(buffer, s.text.data() + s.offset, n);
    s.offset += n;
    return static_cast<ssize_t>(n);
  };
  return fopencookie(&stream, "r", functions);
}

// A read error part-way through a file on disk ends its lines where the error came, and is
// recorded as an I/O error that names the file and the system's reason (read_deck_file then
// fails with exit 3), not as a diagnostic of the deck.
TEST(FileScan, ReadErrorPartWayIsAnIoErrorNamingTheFile) {
  const std::string text = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n";
  const TemporaryDeck deck(text);
  SourceManager sources;
  const std::optional<std::uint32_t> index = load(deck, sources);
  ASSERT_TRUE(index);
  FailingStream stream{text, 20};  // "*NODE\n1, 0., 0., 0.\n" and nothing after
  std::FILE* handle = open_failing_stream(stream);
  ASSERT_NE(handle, nullptr);
  DiagnosticSink sink;
  LineScanner scanner(std::make_unique<FileWindow>(handle, 8), *index, sink);
  const std::vector<ScannedLine> lines = scan_all(scanner);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1].text, "1, 0., 0., 0.");
  EXPECT_TRUE(scanner.read_failed());
  EXPECT_EQ(scanner.read_error(), std::strerror(EIO));
  check_read_whole(sources, scanner, *index, sink);
  EXPECT_TRUE(sink.diagnostics().empty());
  EXPECT_EQ(sources.read_error(), "cannot read '" + deck.path() + "' after 20 bytes: " +
                                      std::strerror(EIO));
}

// The bound a block's handler reserves by: every line up to the next keyword line, comments
// included (an over-count is harmless), and the last line of a file without a line end.
TEST(SourceManager, KeywordLinesRecordedByTheFirstPassBoundEachBlock) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  read_deck_text("t.inp", "*NODE\n1, 0.\n** comment\n2, 1.\n*ELEMENT, TYPE=CONN3D2\n1, 1, 2",
                 sources, model, sink);
  EXPECT_EQ(sources.lines_after_keyword({0, 1, 1}), 3u);
  EXPECT_EQ(sources.lines_after_keyword({0, 5, 1}), 1u);
  EXPECT_EQ(sources.lines_after_keyword({0, 7, 1}), 0u);  // past the end
  EXPECT_EQ(sources.lines_after_keyword({1, 1, 1}), 0u);  // no such file
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
