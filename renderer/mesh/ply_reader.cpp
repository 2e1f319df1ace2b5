// The PLY reader (see mesh_formats.h): ascii, binary_little_endian and binary_big_endian; the
// "vertex" element's x, y, z (any numeric type, double kept as double) and the "face" element's
// index list ("vertex_indices" or "vertex_index"); other elements and properties are skipped.
// The header is checked before anything is allocated: every property belongs to an element,
// every type is known, and each element's count times its smallest possible size fits in the
// bytes that follow.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"
#include "renderer/mesh/text_cursor.h"

namespace npr {
namespace {

enum class Format { Ascii, BinaryLE, BinaryBE };
enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parseType(std::string_view s, Type& t) {
  static const std::pair<std::string_view, Type> names[] = {
      {"char", Type::Int8},     {"int8", Type::Int8},     {"uchar", Type::UInt8},   {"uint8", Type::UInt8},
      {"short", Type::Int16},   {"int16", Type::Int16},   {"ushort", Type::UInt16}, {"uint16", Type::UInt16},
      {"int", Type::Int32},     {"int32", Type::Int32},   {"uint", Type::UInt32},   {"uint32", Type::UInt32},
      {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
  for (const auto& [n, v] : names)
    if (s == n) { t = v; return true; }
  return false;
}

std::size_t sizeOf(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool isList = false;
  Type countType = Type::UInt8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

// Reads values from the body, binary (either byte order) or ascii, never past its end.
class BodyReader {
 public:
  BodyReader(Format f, const char* begin, const char* end) : format_(f), p_(begin), end_(end), text_(begin, end) {}

  std::size_t left() const { return static_cast<std::size_t>(end_ - (format_ == Format::Ascii ? text_.position() : p_)); }

  bool read(Type t, double& out) {
    if (format_ == Format::Ascii) {
      text_.skipSpaceAndComments();
      return text_.number(out);
    }
    const std::size_t n = sizeOf(t);
    if (static_cast<std::size_t>(end_ - p_) < n) return false;
    unsigned char b[8];
    std::memcpy(b, p_, n);
    p_ += n;
    if (format_ == Format::BinaryBE) std::reverse(b, b + n);
    switch (t) {
      case Type::Int8: { std::int8_t v; std::memcpy(&v, b, 1); out = v; break; }
      case Type::UInt8: out = b[0]; break;
      case Type::Int16: { std::int16_t v; std::memcpy(&v, b, 2); out = v; break; }
      case Type::UInt16: { std::uint16_t v; std::memcpy(&v, b, 2); out = v; break; }
      case Type::Int32: { std::int32_t v; std::memcpy(&v, b, 4); out = v; break; }
      case Type::UInt32: { std::uint32_t v; std::memcpy(&v, b, 4); out = v; break; }
      case Type::Float32: { float v; std::memcpy(&v, b, 4); out = v; break; }
      case Type::Float64: { double v; std::memcpy(&v, b, 8); out = v; break; }
    }
    return true;
  }

  // Reads a list's length and checks that so many items can still follow.
  bool listLength(const Property& prop, std::uint64_t& n) {
    double c = 0.0;
    if (!read(prop.countType, c) || !(c >= 0.0) || c != std::floor(c)) return false;
    const std::size_t itemMin = format_ == Format::Ascii ? 2 : sizeOf(prop.type);
    if (c > double(left() / itemMin + 1)) return false;
    n = static_cast<std::uint64_t>(c);
    return true;
  }

  // The smallest number of bytes one value can take: what counts are checked against.
  std::size_t minSize(Type t) const { return format_ == Format::Ascii ? 2 : sizeOf(t); }

 private:
  Format format_;
  const char* p_;
  const char* end_;
  TextCursor text_;
};

}  // namespace

Result<Mesh> parsePly(const std::string& name, std::string bytes) {
  TextCursor header(bytes.data(), bytes.data() + bytes.size());
  auto at = [&](const std::string& what) { return Error{name + " line " + std::to_string(header.line()) + ": " + what}; };
  auto lineRest = [&] {
    header.skipBlanks();
    const char* s = header.position();
    const char* e = s;
    while (e < bytes.data() + bytes.size() && *e != '\n') ++e;
    std::string_view v(s, static_cast<std::size_t>(e - s));
    while (!v.empty() && (v.back() == '\r' || v.back() == ' ')) v.remove_suffix(1);
    return v;
  };
  if (header.token() != "ply") return Error{name + ": not a PLY file (it does not start with 'ply')"};
  header.skipLine();
  Format format = Format::Ascii;
  bool haveFormat = false, ended = false;
  std::vector<Element> elements;
  while (!header.atEnd() && !ended) {
    header.skipBlanks();
    if (header.atEndOfLine()) { header.skipLine(); continue; }
    const std::string_view key = header.token();
    if (key == "comment" || key == "obj_info") {
    } else if (key == "format") {
      const std::string_view f = header.token();
      if (f == "ascii") format = Format::Ascii;
      else if (f == "binary_little_endian") format = Format::BinaryLE;
      else if (f == "binary_big_endian") format = Format::BinaryBE;
      else return at("unknown PLY format '" + std::string(f.substr(0, 32)) + "'");
      haveFormat = true;
    } else if (key == "element") {
      Element e;
      e.name = std::string(header.token().substr(0, 64));
      if (e.name.empty() || !header.integer(e.count)) return at("'element' needs a name and a count");
      elements.push_back(std::move(e));
    } else if (key == "property") {
      if (elements.empty()) return at("'property' before any 'element'");
      Property prop;
      std::string_view t = header.token();
      if (t == "list") {
        prop.isList = true;
        if (!parseType(header.token(), prop.countType) || !isInteger(prop.countType)) return at("a list's count type must be an integer type");
        t = header.token();
      }
      if (!parseType(t, prop.type)) return at("unknown property type '" + std::string(t.substr(0, 32)) + "'");
      prop.name = std::string(header.token().substr(0, 64));
      if (prop.name.empty()) return at("property without a name");
      elements.back().properties.push_back(std::move(prop));
    } else if (key == "end_header") {
      ended = true;
    } else {
      return at("unknown header line '" + std::string(lineRest().substr(0, 40)) + "'");
    }
    header.skipLine();
  }
  if (!ended) return Error{name + ": the PLY header has no 'end_header' line"};
  if (!haveFormat) return Error{name + ": the PLY header has no 'format' line"};

  const char* body = header.position();
  BodyReader in(format, body, bytes.data() + bytes.size());
  // Every element must fit in the bytes that follow, or the header lies (an absurd count would
  // otherwise allocate without bound).
  {
    long double need = 0;
    for (const Element& e : elements) {
      std::size_t per = 0;
      for (const Property& p : e.properties) per += p.isList ? in.minSize(p.countType) : in.minSize(p.type);
      need += static_cast<long double>(e.count) * static_cast<long double>(per);
    }
    if (need > static_cast<long double>(in.left()) + (format == Format::Ascii ? 1 : 0))
      return Error{name + ": the header's element counts need at least " +
                   (need < 1e18L ? std::to_string(static_cast<unsigned long long>(need)) : std::string("10^18")) + " bytes but only " +
                   std::to_string(in.left()) + " follow: the header is corrupt or the file truncated"};
  }

  LoadReport report;
  report.file = name;
  Warnings warn(report.warnings);
  PolygonSoup soup;
  FaceBuilder faces(soup, report, warn);
  std::vector<long long> corners;
  bool sawVertices = false;
  for (const Element& e : elements) {
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    int xyz[3] = {-1, -1, -1};
    int indexList = -1;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const Property& p = e.properties[k];
      if (isVertex && !p.isList) {
        if (p.name == "x") xyz[0] = int(k);
        if (p.name == "y") xyz[1] = int(k);
        if (p.name == "z") xyz[2] = int(k);
      }
      if (isFace && p.isList && (p.name == "vertex_indices" || p.name == "vertex_index" || indexList < 0)) indexList = int(k);
    }
    if (e.properties.empty()) continue;  // takes no bytes, whatever its count says
    if (isVertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)) return Error{name + ": the 'vertex' element has no x, y and z properties"};
    if (isVertex) {
      sawVertices = true;
      soup.vertices.reserve(e.count);
      soup.vertexValid.reserve(e.count);
    }
    if (isFace) soup.triangles.reserve(e.count);
    std::size_t badVertices = 0;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      glm::dvec3 v(0.0);
      corners.clear();
      bool faceOk = true;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (!p.isList) {
          double value = 0.0;
          if (!in.read(p.type, value))
            return Error{name + ": element '" + e.name + "' " + std::to_string(i) + " is cut short (file truncated or values missing)"};
          for (int c = 0; c < 3; ++c) if (int(k) == xyz[c]) v[c] = value;
          continue;
        }
        std::uint64_t n = 0;
        if (!in.listLength(p, n))
          return Error{name + ": element '" + e.name + "' " + std::to_string(i) + ": list '" + p.name + "' has a negative or impossible length"};
        for (std::uint64_t j = 0; j < n; ++j) {
          double value = 0.0;
          if (!in.read(p.type, value))
            return Error{name + ": element '" + e.name + "' " + std::to_string(i) + " is cut short (file truncated or values missing)"};
          if (int(k) != indexList) continue;
          if (!(value >= -1e15 && value <= 1e15) || value != std::floor(value)) faceOk = false;  // not an index
          else corners.push_back(static_cast<long long>(value));
        }
      }
      if (isVertex && !soup.addVertex(v)) ++badVertices;
      if (isFace) {
        if (!sawVertices) return Error{name + ": faces come before the vertices they use"};
        if (!faceOk) {
          warn.add(name + " face " + std::to_string(i) + ": an index is not an integer; face skipped");
          ++report.skipped_faces;
        } else {
          faces.add(corners, "face", i);
        }
      }
    }
    if (badVertices) warn.add(name + ": " + std::to_string(badVertices) + " vertices have non-finite coordinates; faces using them are skipped");
  }
  warn.finish();
  std::string().swap(bytes);  // not needed while building
  return buildMesh(std::move(soup), std::move(report));
}

}  // namespace npr
