#include "base/json_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>
#include <vector>

#include "base/input_error.h"

using nlohmann::json;

namespace {

// What a non-regular file is, for the message.
std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string bytes(std::uintmax_t count) {
  if (count >= (std::uintmax_t(1) << 20)) return std::to_string(count >> 20) + " MiB";
  return std::to_string(count) + " bytes";
}

// The limits, checked before the document is built. Stops at the first problem.
class Limits : public nlohmann::json_sax<json> {
 public:
  std::string problem, pointerOfProblem;
  bool syntaxError = false;

  bool start_object(std::size_t) override { return push(true); }
  bool end_object() override { return pop(); }
  bool start_array(std::size_t) override { return push(false); }
  bool end_array() override { return pop(); }
  bool key(string_t& name) override {
    Level& level = levels_.back();
    level.key = name;
    if (name.size() > kMaxJsonString)
      return stop("a key of " + bytes(name.size()) + " (at most " + bytes(kMaxJsonString) + ")");
    if (!level.keys.insert(name).second) return stop("key given twice");
    return true;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t& text) override {
    if (!value()) return false;
    if (text.size() > kMaxJsonString)
      return stop("a string of " + bytes(text.size()) + " (at most " + bytes(kMaxJsonString) + ")");
    return true;
  }
  bool binary(binary_t&) override { return value(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
    // Drop the "[json.exception.parse_error.101] " prefix; keep line and column.
    const std::string what = error.what();
    const size_t bracket = what.find("] ");
    problem = bracket == std::string::npos ? what : what.substr(bracket + 2);
    syntaxError = true;
    return false;
  }

 private:
  struct Level {
    bool isObject;
    std::set<std::string> keys;
    std::string key;
    size_t index = 0;
  };
  bool value() {
    if (!levels_.empty() && !levels_.back().isObject) ++levels_.back().index;
    return true;
  }
  bool push(bool isObject) {
    value();
    levels_.push_back({isObject, {}, {}, 0});
    if (int(levels_.size()) > kMaxJsonDepth)
      return stop("nested deeper than " + std::to_string(kMaxJsonDepth) + " levels", true);
    return true;
  }
  bool pop() {
    levels_.pop_back();
    return true;
  }
  // `container`: the pointer of the innermost container itself (too deep), else of its
  // current key or element.
  bool stop(const std::string& what, bool container = false) {
    problem = what;
    pointerOfProblem = pointer(container ? levels_.size() - 1 : levels_.size());
    return false;
  }
  std::string pointer(size_t depth) const {
    std::string result;
    for (size_t i = 0; i < depth; ++i) {
      const Level& level = levels_[i];
      result = level.isObject ? jsonPointer(result, level.key)
                              : result + "/" + std::to_string(level.index == 0 ? 0 : level.index - 1);
      if (result.size() > 200) return printable(result, 200);  // a pointer of 64 long keys
    }
    return result;
  }
  std::vector<Level> levels_;
};

}  // namespace

std::string regularFileProblem(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return errno == ENOENT ? "no such file" : std::strerror(errno);
  if (!S_ISREG(info.st_mode)) return kindOf(info.st_mode) + ", not a regular file";
  return "";
}

std::string readInputFile(const std::string& path, std::uintmax_t maxBytes) {
  const auto fail = [&](const std::string& why) -> std::string {
    throw InputError(printable(path, 200) + ": " + why);
  };
  if (path.empty()) throw InputError("an empty file name");
  if (std::string problem = regularFileProblem(path); !problem.empty()) fail(problem);
  struct stat info {};
  // O_NONBLOCK: should the path be swapped for a FIFO after the check, open does not wait
  // for a writer; fstat below then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &info) != 0) fail(std::strerror(errno));
  if (!S_ISREG(info.st_mode)) fail(kindOf(info.st_mode) + ", not a regular file");
  if (std::uintmax_t(info.st_size) > maxBytes)
    fail(bytes(std::uintmax_t(info.st_size)) + " (at most " + bytes(maxBytes) + ")");
  std::string text(size_t(info.st_size), '\0');
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t got = ::read(fd, text.data() + done, text.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(std::strerror(errno));
    if (got == 0) break;  // shrank while reading
    done += size_t(got);
  }
  text.resize(done);
  return text;
}

json parseJsonText(const std::string& text, const std::string& path) {
  const std::string name = printable(path, 200);
  if (text.size() > kMaxJsonBytes)
    throw InputError(name + ": " + bytes(text.size()) + " (at most " + bytes(kMaxJsonBytes) + ")");
  Limits limits;
  json::sax_parse(text, &limits);
  if (limits.syntaxError) throw InputError(name + ": not valid JSON: " + limits.problem);
  if (!limits.problem.empty())
    throw InputError(name + ": " + (limits.pointerOfProblem.empty() ? "/" : limits.pointerOfProblem) +
                     ": " + limits.problem);
  try {
    return json::parse(text);
  } catch (const json::exception& error) {  // not expected after the SAX pass
    throw InputError(name + ": not valid JSON: " + error.what());
  }
}

json readJsonFile(const std::string& path) { return parseJsonText(readInputFile(path), path); }

std::string jsonPointer(const std::string& parent, const std::string& key) {
  std::string escaped;
  for (char c : printable(key)) {
    if (c == '~')
      escaped += "~0";
    else if (c == '/')
      escaped += "~1";
    else
      escaped += c;
  }
  return parent + "/" + escaped;
}

std::string shortJson(const json& value, size_t maxBytes) {
  // Strings and scalars are short to dump; containers are dumped whole only when small.
  return printable(value.dump(-1, ' ', false, json::error_handler_t::replace), maxBytes);
}

std::string plainText(const std::string& text, size_t maxBytes) {
  std::string result;
  result.reserve(std::min(text.size(), maxBytes));
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) continue;
    // C1 controls (U+0080..U+009F, e.g. CSI) act on terminals too.
    if (!result.empty() && static_cast<unsigned char>(result.back()) == 0xC2 && c >= 0x80 && c <= 0x9F) {
      result.pop_back();
      continue;
    }
    result += ch;
  }
  if (result.size() <= maxBytes) return result;
  size_t cut = maxBytes;
  while (cut > 0 && (static_cast<unsigned char>(result[cut]) & 0xC0) == 0x80) --cut;  // continuation
  result.resize(cut);
  return result + " ...";
}
