#include "mcap/ros2msg.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>

namespace tactile::mcap::ros2 {

std::string normalizeTypeName(std::string_view name) {
  std::string out(name);
  const std::size_t at = out.find("/msg/");
  if (at != std::string::npos) out.erase(at, 4);
  return out;
}

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::optional<Primitive> primitiveNamed(std::string_view name) {
  static const std::map<std::string_view, Primitive> kNames{
      {"bool", Primitive::Bool},       {"byte", Primitive::Byte},
      {"char", Primitive::Char},       {"int8", Primitive::Int8},
      {"uint8", Primitive::UInt8},     {"int16", Primitive::Int16},
      {"uint16", Primitive::UInt16},   {"int32", Primitive::Int32},
      {"uint32", Primitive::UInt32},   {"int64", Primitive::Int64},
      {"uint64", Primitive::UInt64},   {"float32", Primitive::Float32},
      {"float64", Primitive::Float64}, {"string", Primitive::String},
      {"wstring", Primitive::WString},
  };
  const auto it = kNames.find(name);
  if (it == kNames.end()) return std::nullopt;
  return it->second;
}

bool parseCount(std::string_view s, std::uint32_t& out) {
  if (s.empty() || s.size() > 9) return false;
  std::uint32_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<std::uint32_t>(c - '0');
  }
  out = v;
  return true;
}

struct PendingField {
  FieldDef field;
  std::string typeName;  // for messages, the resolved "pkg/Type"
  std::size_t line = 0;
};

struct Section {
  std::string name;
  std::vector<PendingField> fields;
};

}  // namespace

Result<Definitions> parseDefinitions(std::string_view schemaName, std::string_view text) {
  const std::string where = "schema " + std::string(schemaName);
  auto fail = [&](std::size_t line, const std::string& message) {
    return Error(where + ", line " + std::to_string(line) + ": " + message);
  };
  std::vector<Section> sections(1);
  sections[0].name = normalizeTypeName(schemaName);
  bool expectMsgLine = false;
  std::size_t lineNo = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(start, end - start));
    start = end + 1;
    ++lineNo;
    if (line.empty()) {
      if (end == text.size()) break;
      continue;
    }
    if (line.size() >= 3 && line.find_first_not_of('=') == std::string_view::npos) {
      expectMsgLine = true;
      continue;
    }
    if (expectMsgLine) {
      if (line.substr(0, 4) != "MSG:") {
        return fail(lineNo, "expected 'MSG: pkg/Type' after a line of '='");
      }
      Section s;
      s.name = normalizeTypeName(trim(line.substr(4)));
      if (s.name.empty()) return fail(lineNo, "a 'MSG:' line without a type name");
      sections.push_back(std::move(s));
      expectMsgLine = false;
      continue;
    }
    if (line.front() == '#') continue;
    // TYPE NAME [DEFAULT] [# comment], or TYPE NAME=VALUE (a constant).
    std::size_t sp = line.find_first_of(" \t");
    if (sp == std::string_view::npos)
      return fail(lineNo, "expected 'TYPE NAME', found '" + std::string(line) + "'");
    std::string_view typeText = line.substr(0, sp);
    std::string_view rest = trim(line.substr(sp));
    const std::size_t nameEnd = rest.find_first_of(" \t=#");
    const std::string_view name = rest.substr(0, nameEnd);
    if (name.empty()) return fail(lineNo, "a field without a name");
    if (nameEnd != std::string_view::npos) {
      const std::string_view after = trim(rest.substr(nameEnd));
      if (!after.empty() && after.front() == '=') continue;  // a constant
    }
    PendingField pf;
    pf.line = lineNo;
    pf.field.name = std::string(name);
    // Array suffix.
    if (const std::size_t br = typeText.find('['); br != std::string_view::npos) {
      if (typeText.back() != ']')
        return fail(lineNo, "malformed array type '" + std::string(typeText) + "'");
      std::string_view inside = typeText.substr(br + 1, typeText.size() - br - 2);
      typeText = typeText.substr(0, br);
      if (inside.empty()) {
        pf.field.array = FieldDef::Array::Sequence;
      } else if (inside.substr(0, 2) == "<=") {
        pf.field.array = FieldDef::Array::Sequence;
        if (!parseCount(inside.substr(2), pf.field.length)) {
          return fail(lineNo, "malformed array bound '" + std::string(inside) + "'");
        }
      } else {
        pf.field.array = FieldDef::Array::Fixed;
        if (!parseCount(inside, pf.field.length)) {
          return fail(lineNo, "malformed array length '" + std::string(inside) + "'");
        }
      }
    }
    // Bounded strings: string<=N.
    if (const std::size_t le = typeText.find("<="); le != std::string_view::npos) {
      typeText = typeText.substr(0, le);
      if (typeText != "string" && typeText != "wstring") {
        return fail(lineNo, "only strings may have a bound, found '" + std::string(typeText) + "'");
      }
    }
    if (auto prim = primitiveNamed(typeText)) {
      pf.field.type = *prim;
    } else {
      pf.field.type = Primitive::Message;
      std::string type;
      if (typeText.find('/') != std::string_view::npos) {
        type = normalizeTypeName(typeText);
      } else if (typeText == "Header") {
        type = "std_msgs/Header";
      } else if (typeText == "time" || typeText == "duration") {
        type = typeText == "time" ? "builtin_interfaces/Time" : "builtin_interfaces/Duration";
      } else {
        const std::string& own = sections.back().name;
        const std::size_t slash = own.find('/');
        type = (slash == std::string::npos ? std::string() : own.substr(0, slash + 1)) +
               std::string(typeText);
      }
      if (type.empty() || type.find_first_of(" \t") != std::string::npos) {
        return fail(lineNo, "unknown type '" + std::string(typeText) + "'");
      }
      pf.typeName = std::move(type);
    }
    sections.back().fields.push_back(std::move(pf));
    if (end == text.size()) break;
  }
  if (expectMsgLine) return fail(lineNo, "the text ends after a line of '=' without 'MSG:'");

  Definitions defs;
  std::map<std::string, int> index;
  for (const Section& s : sections) {
    if (index.count(s.name) != 0) continue;  // repeated definitions: the first counts
    index[s.name] = static_cast<int>(defs.types.size());
    defs.types.push_back({s.name, {}});
  }
  auto builtin = [&](const std::string& name) -> int {
    if (name != "builtin_interfaces/Time" && name != "builtin_interfaces/Duration") return -1;
    const int i = static_cast<int>(defs.types.size());
    MessageDef def{name, {}};
    FieldDef sec;
    sec.name = "sec";
    sec.type = Primitive::Int32;
    FieldDef nsec;
    nsec.name = "nanosec";
    nsec.type = Primitive::UInt32;
    def.fields = {sec, nsec};
    defs.types.push_back(std::move(def));
    index[name] = i;
    return i;
  };
  for (const Section& s : sections) {
    MessageDef& def = defs.types[static_cast<std::size_t>(index[s.name])];
    if (!def.fields.empty()) continue;
    for (const PendingField& pf : s.fields) {
      FieldDef f = pf.field;
      if (f.type == Primitive::Message) {
        auto it = index.find(pf.typeName);
        int i = it == index.end() ? builtin(pf.typeName) : it->second;
        if (i < 0) {
          return fail(pf.line, "type '" + pf.typeName + "' of field '" + f.name +
                                   "' is not defined in the schema (no 'MSG: " + pf.typeName +
                                   "' section)");
        }
        f.message = i;
      }
      defs.types[static_cast<std::size_t>(index[s.name])].fields.push_back(std::move(f));
    }
  }
  // A type may not contain itself (it would have no end).
  std::vector<int> state(defs.types.size(), 0);
  std::function<bool(int)> cyclic = [&](int t) {
    if (state[static_cast<std::size_t>(t)] == 1) return true;
    if (state[static_cast<std::size_t>(t)] == 2) return false;
    state[static_cast<std::size_t>(t)] = 1;
    for (const FieldDef& f : defs.types[static_cast<std::size_t>(t)].fields) {
      if (f.type == Primitive::Message && cyclic(f.message)) return true;
    }
    state[static_cast<std::size_t>(t)] = 2;
    return false;
  };
  for (std::size_t t = 0; t < defs.types.size(); ++t) {
    if (cyclic(static_cast<int>(t))) {
      return Error(where + ": type " + defs.types[t].name + " contains itself");
    }
  }
  return defs;
}

// ---- decoding ----------------------------------------------------------------------------

Result<Decoder> Decoder::make(const Definitions& defs, const std::vector<std::string>& paths) {
  Decoder d;
  d.defs_ = defs;
  d.plans_.push_back({0, std::vector<Action>(defs.types[0].fields.size())});
  d.pathIsArray_.assign(paths.size(), false);
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const std::string& path = paths[k];
    int plan = 0;
    std::size_t from = 0;
    while (true) {
      const std::size_t dot = path.find('.', from);
      const std::string part =
          path.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
      const MessageDef& type =
          d.defs_.types[static_cast<std::size_t>(d.plans_[static_cast<std::size_t>(plan)].type)];
      const auto it = std::find_if(type.fields.begin(), type.fields.end(),
                                   [&](const FieldDef& f) { return f.name == part; });
      if (it == type.fields.end()) {
        return Error("field '" + path + "': " + type.name + " has no field '" + part + "'");
      }
      const auto fi = static_cast<std::size_t>(it - type.fields.begin());
      if (dot == std::string::npos) {
        if (it->type == Primitive::Message || it->type == Primitive::String ||
            it->type == Primitive::WString) {
          return Error("field '" + path + "' of " + type.name + " is not a number");
        }
        Action& a = d.plans_[static_cast<std::size_t>(plan)].actions[fi];
        a.kind = it->array == FieldDef::Array::None ? Action::Kind::Scalar : Action::Kind::Array;
        a.slot = static_cast<int>(k);
        d.pathIsArray_[k] = a.kind == Action::Kind::Array;
        break;
      }
      if (it->type != Primitive::Message || it->array != FieldDef::Array::None) {
        return Error("field '" + path + "': '" + part + "' of " + type.name +
                     " is not a single message");
      }
      Action a = d.plans_[static_cast<std::size_t>(plan)].actions[fi];
      if (a.kind != Action::Kind::Child) {
        a.kind = Action::Kind::Child;
        a.child = static_cast<int>(d.plans_.size());
        d.plans_[static_cast<std::size_t>(plan)].actions[fi] = a;
        d.plans_.push_back(
            {it->message, std::vector<Action>(
                              d.defs_.types[static_cast<std::size_t>(it->message)].fields.size())});
      }
      plan = a.child;
      from = dot + 1;
    }
  }
  return d;
}

namespace {

struct DecodeFault {
  std::string message;
};

std::size_t primitiveSize(Primitive p) {
  switch (p) {
    case Primitive::Bool:
    case Primitive::Byte:
    case Primitive::Char:
    case Primitive::Int8:
    case Primitive::UInt8:
      return 1;
    case Primitive::Int16:
    case Primitive::UInt16:
      return 2;
    case Primitive::Int32:
    case Primitive::UInt32:
    case Primitive::Float32:
      return 4;
    case Primitive::Int64:
    case Primitive::UInt64:
    case Primitive::Float64:
      return 8;
    case Primitive::String:
    case Primitive::WString:
    case Primitive::Message:
      break;
  }
  return 0;
}

class Cursor {
 public:
  Cursor(const unsigned char* data, std::size_t size, bool swap, std::size_t maxAlign)
      : data_(data), size_(size), swap_(swap), maxAlign_(maxAlign) {}

  bool swaps() const { return swap_; }
  void align(std::size_t n) {
    const std::size_t a = std::min(n, maxAlign_);
    const std::size_t next = (pos_ + a - 1) / a * a;
    if (next > size_) fault("the message ends at byte " + std::to_string(size_ + 4));
    pos_ = next;
  }
  void need(std::size_t n) {
    if (size_ - pos_ < n) {
      fault("the message ends at byte " + std::to_string(size_ + 4) + ", inside a field at byte " +
            std::to_string(pos_ + 4));
    }
  }
  std::uint32_t count() {
    align(4);
    need(4);
    std::uint32_t v;
    std::memcpy(&v, data_ + pos_, 4);
    if (swap_) v = __builtin_bswap32(v);
    pos_ += 4;
    return v;
  }
  double primitive(Primitive p) {
    const std::size_t n = primitiveSize(p);
    align(n);
    need(n);
    const double v = value(p, data_ + pos_);
    pos_ += n;
    return v;
  }
  double value(Primitive p, const unsigned char* at) const {
    switch (p) {
      case Primitive::Bool:
      case Primitive::Byte:
      case Primitive::Char:
      case Primitive::UInt8:
        return *at;
      case Primitive::Int8:
        return static_cast<std::int8_t>(*at);
      case Primitive::Int16:
        return static_cast<std::int16_t>(load<std::uint16_t>(at));
      case Primitive::UInt16:
        return load<std::uint16_t>(at);
      case Primitive::Int32:
        return static_cast<std::int32_t>(load<std::uint32_t>(at));
      case Primitive::UInt32:
        return load<std::uint32_t>(at);
      case Primitive::Int64:
        return static_cast<double>(static_cast<std::int64_t>(load<std::uint64_t>(at)));
      case Primitive::UInt64:
        return static_cast<double>(load<std::uint64_t>(at));
      case Primitive::Float32: {
        const std::uint32_t bits = load<std::uint32_t>(at);
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
      }
      case Primitive::Float64: {
        const std::uint64_t bits = load<std::uint64_t>(at);
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
      }
      case Primitive::String:
      case Primitive::WString:
      case Primitive::Message:
        break;
    }
    return 0.0;
  }
  void skip(std::size_t n) {
    need(n);
    pos_ += n;
  }
  // `count` elements of `size` bytes: checked without overflow.
  void needElements(std::uint64_t count, std::size_t size) {
    if (count > (size_ - pos_) / std::max<std::size_t>(size, 1)) {
      fault("a sequence of " + std::to_string(count) + " elements at byte " +
            std::to_string(pos_ + 4) + " runs past the end of the message (" +
            std::to_string(size_ + 4) + " bytes)");
    }
  }
  const unsigned char* here() const { return data_ + pos_; }
  std::size_t remaining() const { return size_ - pos_; }
  [[noreturn]] static void fault(std::string message) { throw DecodeFault{std::move(message)}; }

 private:
  template <class T>
  T load(const unsigned char* at) const {
    T v;
    std::memcpy(&v, at, sizeof v);
    if (swap_) {
      if constexpr (sizeof(T) == 2) v = __builtin_bswap16(v);
      if constexpr (sizeof(T) == 4) v = __builtin_bswap32(v);
      if constexpr (sizeof(T) == 8) v = __builtin_bswap64(v);
    }
    return v;
  }

  const unsigned char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  bool swap_;
  std::size_t maxAlign_;
};

struct Walker {
  const Definitions& defs;
  const std::vector<Decoder::Plan>& plans;
  Cursor& c;
  std::vector<double>& scalars;
  std::vector<std::vector<double>>& arrays;

  void skipOne(const FieldDef& f) {
    switch (f.type) {
      case Primitive::String: {
        const std::uint32_t n = c.count();
        c.skip(n);
        return;
      }
      case Primitive::WString:
        Cursor::fault("wstring fields are not supported");
      case Primitive::Message:
        skipStruct(f.message);
        return;
      default:
        c.primitive(f.type);
        return;
    }
  }

  void skipField(const FieldDef& f) {
    if (f.array == FieldDef::Array::None) {
      skipOne(f);
      return;
    }
    const std::uint64_t n = f.array == FieldDef::Array::Fixed ? f.length : c.count();
    const std::size_t size = primitiveSize(f.type);
    if (size > 0) {
      if (n == 0) return;
      c.align(size);
      c.needElements(n, size);
      c.skip(static_cast<std::size_t>(n) * size);
      return;
    }
    c.needElements(n, 1);
    for (std::uint64_t i = 0; i < n; ++i)
      skipOne(f);
  }

  void skipStruct(int type) {
    for (const FieldDef& f : defs.types[static_cast<std::size_t>(type)].fields)
      skipField(f);
  }

  void readArray(const FieldDef& f, std::vector<double>& out) {
    const std::uint64_t n = f.array == FieldDef::Array::Fixed ? f.length : c.count();
    const std::size_t size = primitiveSize(f.type);
    out.clear();
    if (n == 0) return;
    c.align(size);
    c.needElements(n, size);
    out.resize(static_cast<std::size_t>(n));
    const unsigned char* at = c.here();
    if (!c.swaps() && f.type == Primitive::Float32) {
      // The common case (a ROS 2 Float32MultiArray on a little-endian host) without a type
      // switch per value.
      for (std::size_t i = 0; i < out.size(); ++i) {
        float v;
        std::memcpy(&v, at + i * 4, 4);
        out[i] = v;
      }
    } else if (!c.swaps() && f.type == Primitive::Float64) {
      std::memcpy(out.data(), at, out.size() * 8);
    } else {
      for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = c.value(f.type, at + i * size);
    }
    c.skip(static_cast<std::size_t>(n) * size);
  }

  void walk(int planIndex) {
    const Decoder::Plan& plan = plans[static_cast<std::size_t>(planIndex)];
    const auto& fields = defs.types[static_cast<std::size_t>(plan.type)].fields;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const Decoder::Action& a = plan.actions[i];
      switch (a.kind) {
        case Decoder::Action::Kind::Skip:
          skipField(fields[i]);
          break;
        case Decoder::Action::Kind::Scalar:
          scalars[static_cast<std::size_t>(a.slot)] = c.primitive(fields[i].type);
          break;
        case Decoder::Action::Kind::Array:
          readArray(fields[i], arrays[static_cast<std::size_t>(a.slot)]);
          break;
        case Decoder::Action::Kind::Child:
          walk(a.child);
          break;
      }
    }
  }
};

}  // namespace

std::optional<std::string> Decoder::decode(std::string_view message, std::vector<double>& scalars,
                                           std::vector<std::vector<double>>& arrays) const {
  if (message.size() < 4) {
    return "a CDR message of " + std::to_string(message.size()) +
           " bytes has no 4-byte encapsulation header";
  }
  const auto* raw = reinterpret_cast<const unsigned char*>(message.data());
  const unsigned kind = (static_cast<unsigned>(raw[0]) << 8) | raw[1];
  bool little = false;
  std::size_t maxAlign = 8;
  switch (kind) {
    case 0x0000:  // CDR_BE (XCDR1)
      break;
    case 0x0001:  // CDR_LE
      little = true;
      break;
    case 0x0006:  // CDR2_BE (plain XCDR2)
      maxAlign = 4;
      break;
    case 0x0007:  // CDR2_LE
      little = true;
      maxAlign = 4;
      break;
    default: {
      char buf[8];
      std::snprintf(buf, sizeof buf, "0x%04X", kind);
      return std::string("unsupported CDR representation ") + buf +
             " (this reader knows plain CDR and XCDR2, little- and big-endian)";
    }
  }
  const bool hostLittle = std::endian::native == std::endian::little;
  if (scalars.size() < pathIsArray_.size()) scalars.resize(pathIsArray_.size(), 0.0);
  if (arrays.size() < pathIsArray_.size()) arrays.resize(pathIsArray_.size());
  Cursor c(raw + 4, message.size() - 4, little != hostLittle, maxAlign);
  Walker w{defs_, plans_, c, scalars, arrays};
  try {
    w.walk(0);
  } catch (const DecodeFault& f) {
    return f.message;
  }
  return std::nullopt;
}

}  // namespace tactile::mcap::ros2
