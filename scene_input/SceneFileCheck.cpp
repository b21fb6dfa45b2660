#include "scene_input/SceneFileCheck.h"

#include "scene/InputError.h"
#include "scene_input/SceneLoader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
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

  // Characters not read yet.
  std::size_t remaining() const { return text_.size() - std::min(at_, text_.size()); }

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

// The fields that name a file Coin opens while reading or drawing the scene. Scenes (File,
// VRMLInline, which Coin reads as a file) are read and checked in turn; a '%' in a name Coin
// cannot find is taken as printf's format in its message (SoInput::pushFile, Coin 4.0), and
// SoTexture3 does the same with every name it fails to read. Coin 4.0 reports the other
// names through "%s". VRML97 nodes are named here as Inventor files spell them; a VRML97
// file spells them without "VRML" (Coin adds it).
struct FileField {
  const char* node;
  const char* field;
  bool scene;         // read as Inventor or VRML, checked in turn
  bool percentKills;  // a '%' crashes Coin whether or not the file is there
  bool firstOnly;     // Coin reads only the first name of the list (url[0])
};
constexpr FileField kFileFields[] = {
    {"File", "name", true, false, false},
    {"VRMLInline", "url", true, false, true},
    {"Texture2", "filename", false, false, false},
    {"Texture3", "filenames", false, true, false},
    {"BumpMap", "filename", false, false, false},
    {"TextureCubeMap", "filenames", false, false, false},
    {"Image", "filename", false, false, false},
    // Shader sources name a file unless they hold the program itself, which names none.
    {"VertexShader", "sourceProgram", false, false, false},
    {"FragmentShader", "sourceProgram", false, false, false},
    {"GeometryShader", "sourceProgram", false, false, false},
    {"VRMLImageTexture", "url", false, false, true},
    {"VRMLBackground", "backUrl", false, false, true},
    {"VRMLBackground", "bottomUrl", false, false, true},
    {"VRMLBackground", "frontUrl", false, false, true},
    {"VRMLBackground", "leftUrl", false, false, true},
    {"VRMLBackground", "rightUrl", false, false, true},
    {"VRMLBackground", "topUrl", false, false, true},
};

// An EXTERNPROTO's url list (VRML97), which Coin fetches as a file through SoInput::pushFile
// like an Inline (a '%' in a name it cannot find crashed the reader; /dev/zero hung it).
constexpr FileField kExternProto = {"EXTERNPROTO", "url", true, false, true};

// Fields holding an image inline: its size, then one value per pixel (SoSFImage, SoSFImage3).
struct ImageField {
  const char* node;
  const char* field;
  int dimensions;
};
constexpr ImageField kImageFields[] = {
    {"Texture2", "image", 2},
    {"Image", "image", 2},
    {"BumpMap", "image", 2},
    {"VRMLPixelTexture", "image", 2},
    {"Texture3", "images", 3},
    {"TextureCubeMap", "imagePosX", 2},
    {"TextureCubeMap", "imageNegX", 2},
    {"TextureCubeMap", "imagePosY", 2},
    {"TextureCubeMap", "imageNegY", 2},
    {"TextureCubeMap", "imagePosZ", 2},
    {"TextureCubeMap", "imageNegZ", 2},
};

// Whether a node of type `type` (as the file spells it) is `node` of the tables above.
bool sameNode(const std::string& type, const char* node, bool vrml97) {
  return type == node || (vrml97 && "VRML" + type == node);
}

// Whether `token` is the type of a node whose file names Coin prints as a format.
bool printsNamesAsFormat(const Token& token, bool vrml97) {
  if (token.quoted) return false;
  if (token.text == kExternProto.node) return true;
  for (const FileField& field : kFileFields)
    if ((field.scene || field.percentKills) && sameNode(token.text, field.node, vrml97))
      return true;
  return false;
}

std::string canonicalPath(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path.string() : canonical.string();
}

// The text of a regular file, or nothing where Coin names what it cannot open itself: a
// directory (File { name "." }) opens as a stream on Linux and throws on the first read (found
// by the scene reader fuzzer).
std::optional<std::string> readText(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text;
  // A regular file can still fail to read (/proc/self/mem: EIO on the first read, which
  // libstdc++'s stream buffer throws as a bare basic_filebuf error).
  try {
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const std::exception&) {
    throw InputError(path + ": error: cannot read: " + std::strerror(errno));
  }
  return text;
}

// The header as Coin reads it: its reader drops NUL bytes from the line (found by
// SceneReaderFuzzer: "#Inventor V2.1 asci", 80 NULs and "i" was read as ASCII, and the cycle
// it held, never checked, overflowed the stack).
std::string headerOf(const std::string& text) {
  std::string header = text.substr(0, text.find('\n'));
  header.erase(std::remove(header.begin(), header.end(), '\0'), header.end());
  return header;
}

// Whether Coin reads a file with this header as ASCII Inventor or VRML; binary files are left
// to Coin.
bool readAsAscii(const std::string& header) {
  return header.rfind("#Inventor", 0) == 0 ? header.find("ascii") != std::string::npos
                                           : header.rfind("#VRML", 0) == 0;
}

class Checker {
 public:
  void checkFile(const std::string& path, int nesting) {
    const std::optional<std::string> text = readText(path);
    if (!text) return;
    const std::string header = headerOf(*text);
    if (!readAsAscii(header)) return;
    open_.push_back(canonicalPath(path));
    Reading file(*text, path, nesting, header.rfind("#VRML V2.0", 0) == 0);
    for (Token token; file.tokenizer.next(token);) {
      if (file.percent.line == 0 && token.text.find('%') != std::string::npos) file.percent = token;
      if (file.printsNames.line == 0 && printsNamesAsFormat(token, file.vrml97))
        file.printsNames = token;
      if (!readFieldValue(file, token)) readStructure(file, token);
      file.before = {file.before[1], file.before[2], token};
    }
    refusePercent(file);
    open_.pop_back();
  }

 private:
  // What is known of one file while it is read, token by token.
  struct Reading {
    Reading(const std::string& text, const std::string& path, int nesting, bool vrml97)
        : path(path), nesting(nesting), vrml97(vrml97), tokenizer(text, path) {}
    // How deep the current node is nested, counting the files that include this one.
    int depth() const { return nesting + int(braces.size()); }

    const std::string& path;
    const int nesting;  // the braces open in the files that include this one
    const bool vrml97;
    Tokenizer tokenizer;
    // Per open brace: the DEF name of the node it opens ("" for none). Per DEF name: the
    // depth of the brace of its newest definition while that is open, -1 once it is closed;
    // a USE refers to the newest definition, so a USE of an open one names an ancestor.
    std::vector<std::string> braces;
    std::map<std::string, int> newest;
    // The three tokens before the current one, newest last: "DEF name Type {".
    std::array<Token, 3> before;
    // Per open brace: the type of the node it opens.
    std::vector<std::string> types;
    // The file-naming field whose value comes next, and whether that is a list in brackets.
    const FileField* fileField = nullptr;
    bool inList = false;
    int listIndex = 0;
    // The inline image whose size comes next: its field, and the numbers read so far.
    const ImageField* imageField = nullptr;
    std::vector<long long> imageSize;
    bool useNext = false;
    // The first '%' anywhere in the file's names and values, and the first node that names a
    // file Coin may print as a format: the backstop (refusePercent).
    Token percent;
    Token printsNames;
    // Where an EXTERNPROTO is read: 1 its name next, 2 its interface's '[', 3 inside it, 4 its
    // url or url list next, 5 that list's first name next; 0 none.
    int externProto = 0;
  };

  // A file name or an image size is read only while the tokens are what the field holds:
  // anything else (a brace, IS, a connection) ends it and is read as usual. Whether `token`
  // was the field's value, checked here.
  bool readFieldValue(Reading& file, const Token& token) {
    if (file.externProto != 0) return readExternProto(file, token);
    if (file.fileField != nullptr) return readFileName(file, token);
    if (file.imageField != nullptr) return readImageSize(file, token);
    return false;
  }

  bool readExternProto(Reading& file, const Token& token) {
    if (file.externProto == 1 || (file.externProto == 2 && token.is("[")) ||
        (file.externProto == 3 && token.is("]"))) {
      ++file.externProto;
    } else if (file.externProto == 4 && token.is("[")) {
      file.externProto = 5;
    } else if (file.externProto >= 4) {
      checkNamedFile(file.path, kExternProto, token, file.depth());
      file.externProto = 0;
    } else if (file.externProto == 2) {
      file.externProto = 0;  // not Coin's syntax: Coin reports it
      return false;
    }
    return true;
  }

  bool readFileName(Reading& file, const Token& token) {
    // Inside brackets Coin reads names up to ']', braces included (found by
    // SceneReaderFuzzer: a list holding "the}" and later "1.37%" was left at the brace).
    if (!file.inList && !token.quoted && (token.is("{") || token.is("}") || token.is("]"))) {
      file.fileField = nullptr;
      file.inList = false;
      return false;
    }
    if (!file.inList && token.is("[")) {
      file.inList = true;
      file.listIndex = 0;
    } else if (file.inList && token.is("]")) {
      file.fileField = nullptr;
      file.inList = false;
    } else {
      if (!file.fileField->firstOnly || file.listIndex++ == 0)
        checkNamedFile(file.path, *file.fileField, token, file.depth());
      if (!file.inList) file.fileField = nullptr;
    }
    return true;
  }

  static bool readImageSize(Reading& file, const Token& token) {
    char* end = nullptr;
    const long long value = std::strtoll(token.text.c_str(), &end, 0);
    if (token.quoted || token.text.empty() || *end != '\0') {
      file.imageField = nullptr;
      return false;
    }
    file.imageSize.push_back(value);
    if (int(file.imageSize.size()) == file.imageField->dimensions + 1) {
      checkImageSize(file.path, *file.imageField, file.imageSize, token.line,
                     file.tokenizer.remaining());
      file.imageField = nullptr;
    }
    return true;
  }

  // A token outside a field's value: nodes, their braces, DEF and USE, and the names of the
  // fields whose values are checked.
  void readStructure(Reading& file, const Token& token) {
    if (file.useNext) {
      file.useNext = false;
      const auto found = file.newest.find(token.text);
      if (found != file.newest.end() && found->second > 0)
        throw InputError(locationPrefix(file.path, token.line) + "error: USE " + token.text +
                         " inside the node DEF " + token.text +
                         " itself (a node that contains itself cannot be traversed)");
    } else if (token.is("{")) {
      const bool defined = file.before[0].is("DEF");
      file.braces.push_back(defined ? file.before[1].text : "");
      if (defined) file.newest[file.before[1].text] = int(file.braces.size());
      if (file.depth() > kMaxSceneNesting)
        throw InputError(locationPrefix(file.path, token.line) + "error: nodes nested more than " +
                         std::to_string(kMaxSceneNesting) + " levels deep");
      file.types.push_back(file.before[2].quoted ? std::string() : file.before[2].text);
    } else if (token.is("}")) {
      if (!file.braces.empty()) {  // Coin reports an unbalanced brace itself
        const std::string& name = file.braces.back();
        if (!name.empty() && file.newest[name] == int(file.braces.size())) file.newest[name] = -1;
        file.braces.pop_back();
        file.types.pop_back();
      }
    } else if (token.is("USE")) {
      file.useNext = true;
    } else if (token.is(kExternProto.node)) {
      file.externProto = 1;
    } else if (!file.types.empty() && !token.quoted) {
      readFieldName(file, token);
    }
  }

  // A field of the current node whose value names a file or holds an image comes next.
  void readFieldName(Reading& file, const Token& token) {
    const std::string& type = file.types.back();
    for (const FileField& field : kFileFields) {
      // Coin reads a field's name as an identifier: "name%x.iv" is the field name and a
      // value (found by SceneReaderFuzzer: File { name%no_such_file.iv" }).
      const std::size_t length = std::strlen(field.field);
      const std::string& text = token.text;
      if (!sameNode(type, field.node, file.vrml97) || text.compare(0, length, field.field) != 0 ||
          (text.size() > length &&
           (std::isalnum(static_cast<unsigned char>(text[length])) || text[length] == '_')))
        continue;
      file.fileField = &field;
      file.listIndex = 0;
      if (text.size() > length) {
        checkNamedFile(file.path, field, Token{text.substr(length), token.line, false},
                       file.depth());
        file.fileField = nullptr;
      }
    }
    for (const ImageField& field : kImageFields)
      if (sameNode(type, field.node, file.vrml97) && token.text == field.field) {
        file.imageField = &field;
        file.imageSize.clear();
      }
  }

  // The checks above follow Coin's reader field by field, and each way they fell short of it
  // let a '%' through to a crash (a second Inline, a list holding a brace, a value joined
  // to its field's name). Whatever the file's structure, a '%' in a file with such a node
  // is refused, naming both.
  static void refusePercent(const Reading& file) {
    if (file.percent.line != 0 && file.printsNames.line != 0)
      throw InputError(locationPrefix(file.path, file.percent.line) + "error: '" +
                       file.percent.text + "' holds a '%' in a file holding " +
                       file.printsNames.text + " (line " + std::to_string(file.printsNames.line) +
                       "), a node whose file names Coin may print as a format; remove the '%'");
  }

  // A file named by `field`, found beside the file that names it as Coin finds it: only a
  // regular file (a FIFO or /dev/zero blocked the reader forever), a scene not one of the
  // files being read, and no '%' where Coin would print the name as a format.
  void checkNamedFile(const std::string& path, const FileField& field, const Token& name,
                      int nesting) {
    namespace fs = std::filesystem;
    if (name.text.empty()) return;
    const std::string where = locationPrefix(path, name.line) + "error: " + field.node + " " +
                              field.field + " " + name.text + ": ";
    const fs::path named = name.text;
    const fs::path resolved = named.is_absolute() ? named : fs::path(path).parent_path() / named;
    std::error_code ec;
    const fs::file_status status = fs::status(resolved, ec);
    const bool percent = name.text.find('%') != std::string::npos;
    // Debian's Coin 4.0 reports a File it cannot find with the name as printf's format
    // (SoInput::pushFile): a '%' in it crashed the reader (found by SceneReaderFuzzer:
    // File { name "a%s.iv" }; VRMLInline { url "%s%n.wrl" } the same way).
    if (percent && (field.percentKills || (field.scene && !fs::exists(status))))
      throw InputError(where +
                       (fs::exists(status) ? std::string("names a file, but ")
                                           : "no such file beside " +
                                                 fs::path(path).filename().string() + ", and ") +
                       "Coin cannot report a name holding '%' (rename the file)");
    if (!fs::exists(status)) return;  // Coin says so itself
    if (std::string kind = notRegularFile(status); !kind.empty()) throw InputError(where + kind);
    if (!field.scene) return;
    const std::string canonical = canonicalPath(resolved);
    for (const std::string& file : open_)
      if (file == canonical)
        throw InputError(where + "includes " +
                         (file == open_.back() ? "itself" : "a file that includes it") +
                         " (the scene would never end)");
    checkFile(resolved.string(), nesting);
  }

  // An inline image's declared size against the values the file still holds: one per pixel,
  // each at least one character and a separator. Coin allocates the whole image before
  // reading a value (a Texture3 of 60000 x 60000 x 60000 died in std::bad_alloc).
  static void checkImageSize(const std::string& path, const ImageField& field,
                             const std::vector<long long>& size, int line, std::size_t remaining) {
    long double pixels = 1;
    std::string declared;
    for (int i = 0; i < field.dimensions; ++i) {
      pixels *= std::max(size[std::size_t(i)], 0LL);
      declared += (i > 0 ? " x " : "") + std::to_string(size[std::size_t(i)]);
    }
    const long long components = size[std::size_t(field.dimensions)];
    if (components < 0 || components > 4)
      throw InputError(locationPrefix(path, line) + "error: " + field.node + " " + field.field +
                       " declares " + std::to_string(components) +
                       " components a pixel; expected 0 to 4");
    const long double available = (long double)(remaining + 1) / 2;
    if (components > 0 && pixels > available)
      throw InputError(locationPrefix(path, line) + "error: " + field.node + " " + field.field +
                       " declares " + declared + " pixels; the rest of the file holds at most " +
                       std::to_string((long long)available) + " values");
  }

  std::vector<std::string> open_;  // the files being read, outermost first
};

}  // namespace

std::string notRegularFile(const std::filesystem::file_status& status) {
  namespace fs = std::filesystem;
  if (fs::is_regular_file(status)) return {};
  return std::string("not a regular file (") +
         (fs::is_directory(status)        ? "a directory"
          : fs::is_fifo(status)           ? "a FIFO"
          : fs::is_character_file(status) ? "a character device"
          : fs::is_block_file(status)     ? "a block device"
                                          : "a socket or other special file") +
         "); only regular files are read";
}

void checkSceneFile(const std::string& path) {
  Checker().checkFile(path, 0);
}

}  // namespace ivshadow
