#include "scene_input/CoinMessageCapture.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <cstdio>
#include <iostream>
#include <regex>

namespace ivshadow {
namespace {

// Binary garbage in a file ends up in Coin's messages; show it as \xNN so that terminals and
// logs stay readable.
std::string printable(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    if (c == '\n' || c == '\t' || (c >= 0x20 && c < 0x7f)) {
      out += static_cast<char>(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
      out += escaped;
    }
  }
  return out;
}

CoinMessageCapture::Message parse(const SoError* error, bool isError) {
  CoinMessageCapture::Message message;
  message.isError = isError;
  std::string text = error->getDebugString().getString();
  message.raw = text;
  // Coin appends "\n  Occurred at line N in 'FILE'" to read errors.
  static const std::regex where(R"(\s*Occurred at line\s+(\d+)\s+in\s+'?([^'\n]*)'?\s*$)");
  std::smatch match;
  if (std::regex_search(text, match, where)) {
    message.line = std::stoi(match[1].str());
    message.file = match[2].str();
    text = text.substr(0, static_cast<std::size_t>(match.position(0)));
  }
  static const std::regex preamble(
      R"(^Coin (read error|error|warning|info) in [^:]*:\s*|^Coin read error:\s*)");
  text = std::regex_replace(text, preamble, "");
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  message.text = printable(text);
  return message;
}

void readHandler(const SoError* error, void* self) {
  static_cast<std::vector<CoinMessageCapture::Message>*>(self)->push_back(parse(error, true));
}

void debugHandler(const SoError* error, void* self) {
  const auto* debug = static_cast<const SoDebugError*>(error);
  const bool isError = debug->getSeverity() == SoDebugError::ERROR;
  static_cast<std::vector<CoinMessageCapture::Message>*>(self)->push_back(parse(error, isError));
}

}  // namespace

CoinMessageCapture::CoinMessageCapture() {
  previousReadHandler_ = SoReadError::getHandlerCallback();
  previousReadData_ = SoReadError::getHandlerData();
  previousDebugHandler_ = SoDebugError::getHandlerCallback();
  previousDebugData_ = SoDebugError::getHandlerData();
  SoReadError::setHandlerCallback(readHandler, &messages_);
  SoDebugError::setHandlerCallback(debugHandler, &messages_);
}

CoinMessageCapture::~CoinMessageCapture() {
  SoReadError::setHandlerCallback(previousReadHandler_, previousReadData_);
  SoDebugError::setHandlerCallback(previousDebugHandler_, previousDebugData_);
}

CoinMessageCapture::Message CoinMessageCapture::firstError() const {
  for (const Message& message : messages_) {
    if (message.isError) return message;
  }
  return {};
}

void CoinMessageCapture::forwardExcept(const std::string& benign) const {
  // Inside another capture, the messages go to it rather than to the terminal.
  auto* outer = previousDebugHandler_ == debugHandler
                    ? static_cast<std::vector<Message>*>(previousDebugData_)
                    : nullptr;
  for (const Message& message : messages_) {
    if (message.raw.find(benign) != std::string::npos) continue;
    if (outer != nullptr)
      outer->push_back(message);
    else
      std::cerr << message.raw << '\n';
  }
}

}  // namespace ivshadow
