#include "scene/SceneFileCheck.h"

#include "scene/InputError.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace ivshadow {
namespace {

struct Token {
  std::string text;
  int line = 0;
  bool quoted = false;

  bool is(const char* word) const { return !quoted && text == word; }
};

bool isSpecial(char c) {
  return c == '{' || c == '}' || c == '[' || c == ']' || c == ',' || c == '"' || c == '#' ||
         std::isspace(static_cast<unsigned char>(c));
}

// Inventor's ASCII syntax as names, values, quoted strings and braces, one token at a time
// (files may be large); comments (from '#' to the end of the line) are dropped.
class Tokenizer {
 public:
  Tokenizer(const std::string& text, const std::string& path) : text_(text), path_(path) {}

  bool next(Token& token) {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
        ++at_;
      } else if (c == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (c == '{' || c == '}' || c == '[' || c == ']') {
        token = {std::string(1, c), line_, false};
        ++at_;
        return true;
      } else if (c == '"') {
        token = {{}, line_, true};
        for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
          if (text_[at_] == '\\' && at_ + 1 < text_.size()) ++at_;
          if (text_[at_] == '\n') ++line_;
          token.text += text_[at_];
        }
        ++at_;
        return true;
      } else {
        const std::size_t start = at_;
        while (at_ < text_.size() && !isSpecial(text_[at_])) ++at_;
        if (at_ - start > std::size_t(kMaxSceneTokenLength))
          throw InputError(locationPrefix(path_, line_) + "error: a name or value of " +
                           std::to_string(at_ - start) + " characters (at most " +
                           std::to_string(kMaxSceneTokenLength) + " are read)");
        token = {text_.substr(start, at_ - start), line_, false};
        return true;
      }
    }
    return false;
  }

 private:
  const std::string& text_;
  const std::string& path_;
  std::size_t at_ = 0;
  int line_ = 1;
};

std::string canonicalPath(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path.string() : canonical.string();
}

class Checker {
 public:
  void checkFile(const std::string& path, int nesting) {
    // Coin names what it cannot open; a directory (File { name "." }) opens as a stream on
    // Linux and throws on the first read (found by the scene reader fuzzer).
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return;
    std::ifstream in(path, std::ios::binary);
    if (!in) return;
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The header as Coin reads it: its reader drops NUL bytes from the line (found by
    // SceneReaderFuzzer: "#Inventor V2.1 asci", 80 NULs and "i" was read as ASCII, and the
    // cycle it held, never checked, overflowed the stack).
    std::string header = text.substr(0, text.find('\n'));
    header.erase(std::remove(header.begin(), header.end(), '\0'), header.end());
    const bool ascii = header.rfind("#Inventor", 0) == 0 ? header.find("ascii") != std::string::npos
                                                         : header.rfind("#VRML", 0) == 0;
    if (!ascii) return;
    open_.push_back(canonicalPath(path));

    // Per open brace: the DEF name of the node it opens ("" for none). Per DEF name: the
    // depth of the brace of its newest definition while that is open, -1 once it is closed;
    // a USE refers to the newest definition, so a USE of an open one names an ancestor.
    std::vector<std::string> braces;
    std::map<std::string, int> newest;
    // The three tokens before the current one, newest last: "DEF name Type {".
    std::array<Token, 3> before;
    // Inside `File { ... }`: the depth of its brace, and whether the next token is its name.
    int fileBrace = 0;
    bool fileNameNext = false;
    bool useNext = false;
    Tokenizer tokenizer(text, path);
    for (Token token; tokenizer.next(token);) {
      if (fileNameNext) {
        fileNameNext = false;
        checkInclusion(path, token, nesting + int(braces.size()));
      } else if (useNext) {
        useNext = false;
        const auto found = newest.find(token.text);
        if (found != newest.end() && found->second > 0)
          throw InputError(locationPrefix(path, token.line) + "error: USE " + token.text +
                           " inside the node DEF " + token.text +
                           " itself (a node that contains itself cannot be traversed)");
      } else if (token.is("{")) {
        const bool defined = before[0].is("DEF");
        braces.push_back(defined ? before[1].text : "");
        if (defined) newest[before[1].text] = int(braces.size());
        if (nesting + int(braces.size()) > kMaxSceneNesting)
          throw InputError(locationPrefix(path, token.line) + "error: nodes nested more than " +
                           std::to_string(kMaxSceneNesting) + " levels deep");
        if (before[2].is("File")) fileBrace = int(braces.size());
      } else if (token.is("}")) {
        if (!braces.empty()) {  // Coin reports an unbalanced brace itself
          const std::string& name = braces.back();
          if (!name.empty() && newest[name] == int(braces.size())) newest[name] = -1;
          if (fileBrace == int(braces.size())) fileBrace = 0;
          braces.pop_back();
        }
      } else if (token.is("USE")) {
        useNext = true;
      } else if (token.is("name") && fileBrace == int(braces.size()) && fileBrace > 0) {
        fileNameNext = true;
      }
      before = {before[1], before[2], token};
    }
    open_.pop_back();
  }

 private:
  // The file a File node names, found beside the file that names it as Coin finds it, must
  // not be one of the files being read.
  void checkInclusion(const std::string& path, const Token& name, int nesting) {
    namespace fs = std::filesystem;
    const fs::path named = name.text;
    const fs::path resolved = named.is_absolute() ? named : fs::path(path).parent_path() / named;
    const std::string canonical = canonicalPath(resolved);
    for (const std::string& file : open_)
      if (file == canonical)
        throw InputError(locationPrefix(path, name.line) + "error: File " + name.text +
                         " includes " +
                         (file == open_.back() ? "itself" : "a file that includes it") +
                         " (the scene would never end)");
    // Debian's Coin 4.0 reports a File it cannot find with the name as printf's format
    // (SoInput::pushFile): a '%' in it crashed the reader (found by SceneReaderFuzzer:
    // File { name "a%s.iv" }). Only a missing file is reported, so only that is refused.
    std::error_code ec;
    if (name.text.find('%') != std::string::npos && !fs::exists(resolved, ec))
      throw InputError(locationPrefix(path, name.line) + "error: File " + name.text +
                       ": no such file beside " + fs::path(path).filename().string() +
                       ", and Coin cannot report a missing name holding '%'");
    checkFile(resolved.string(), nesting);
  }

  std::vector<std::string> open_;  // the files being read, outermost first
};

}  // namespace

void checkSceneFile(const std::string& path) {
  Checker().checkFile(path, 0);
}

}  // namespace ivshadow
