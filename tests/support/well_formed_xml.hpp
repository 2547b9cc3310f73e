// A small checker for the XML the SDK writes (SVG plots): tags nest and close, attribute values
// are quoted, text holds no raw '<' and only known entities. Enough to catch a broken writer
// without pulling in an XML library.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ncsdk_test {

// Empty when `xml` is well-formed, otherwise a description of the first problem.
inline std::string xml_problem(std::string_view xml) {
  std::vector<std::string> open;
  std::size_t i = 0;
  bool root_seen = false;
  auto is_name_char = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == ':' || c == '.';
  };
  auto check_entity = [&](std::size_t at) -> bool {
    for (std::string_view entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"}) {
      if (xml.substr(at, entity.size()) == entity) return true;
    }
    return false;
  };
  while (i < xml.size()) {
    const char c = xml[i];
    if (c == '&') {
      if (!check_entity(i)) return "unknown entity at " + std::to_string(i);
      ++i;
      continue;
    }
    if (c == '>') return "stray '>' at " + std::to_string(i);
    if (c != '<') {
      ++i;
      continue;
    }
    if (xml.substr(i, 5) == "<?xml") {
      const auto end = xml.find("?>", i);
      if (end == std::string_view::npos) return "unclosed declaration";
      i = end + 2;
      continue;
    }
    if (xml.substr(i, 4) == "<!--") {
      const auto end = xml.find("-->", i);
      if (end == std::string_view::npos) return "unclosed comment";
      i = end + 3;
      continue;
    }
    const bool closing = i + 1 < xml.size() && xml[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_start = j;
    while (j < xml.size() && is_name_char(xml[j]))
      ++j;
    const std::string name(xml.substr(name_start, j - name_start));
    if (name.empty()) return "tag without a name at " + std::to_string(i);
    if (closing) {
      while (j < xml.size() && xml[j] == ' ')
        ++j;
      if (j >= xml.size() || xml[j] != '>') return "bad closing tag </" + name + ">";
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
      i = j + 1;
      continue;
    }
    if (open.empty()) {
      if (root_seen) return "second root element <" + name + ">";
      root_seen = true;
    }
    // Attributes: name="value" pairs, then '>' or '/>'.
    while (true) {
      while (j < xml.size() && (xml[j] == ' ' || xml[j] == '\n' || xml[j] == '\t'))
        ++j;
      if (j >= xml.size()) return "unterminated tag <" + name + ">";
      if (xml[j] == '>') {
        open.push_back(name);
        i = j + 1;
        break;
      }
      if (xml.substr(j, 2) == "/>") {
        i = j + 2;
        break;
      }
      const std::size_t attr_start = j;
      while (j < xml.size() && is_name_char(xml[j]))
        ++j;
      if (j == attr_start) return "bad attribute in <" + name + ">";
      if (j + 1 >= xml.size() || xml[j] != '=' || (xml[j + 1] != '"' && xml[j + 1] != '\'')) {
        return "unquoted attribute in <" + name + ">";
      }
      const char quote = xml[j + 1];
      const auto end = xml.find(quote, j + 2);
      if (end == std::string_view::npos) return "unterminated attribute in <" + name + ">";
      const std::string_view value = xml.substr(j + 2, end - j - 2);
      if (value.find('<') != std::string_view::npos) return "'<' inside an attribute";
      j = end + 1;
    }
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  if (!root_seen) return "no root element";
  return {};
}

}  // namespace ncsdk_test
