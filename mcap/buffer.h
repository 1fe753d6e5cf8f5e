// A growable byte buffer that is never zero-filled, and an appender that writes into it through a
// local cursor (the exporter formats millions of messages: a cursor held in registers, numbers
// printed straight into the buffer, literals without strlen). Internal to the mcap part.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>

namespace tactile::mcap {

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  char* data() { return data_.get(); }
  const char* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::string_view view() const { return {data_.get(), size_}; }
  void clear() { size_ = 0; }
  char& operator[](std::size_t i) { return data_[i]; }

  // Room for at least n more bytes past the end.
  void reserveMore(std::size_t n) {
    if (capacity_ - size_ < n) grow(n);
  }
  void reserve(std::size_t n) {
    if (n > capacity_) grow(n - size_);
  }
  void push_back(char c) {
    reserveMore(1);
    data_[size_++] = c;
  }
  void append(const char* p, std::size_t n) {
    reserveMore(n);
    if (n > 0) std::memcpy(data_.get() + size_, p, n);
    size_ += n;
  }
  void append(std::string_view s) { append(s.data(), s.size()); }
  // The end moved by a writer that filled reserved room (see Appender).
  void setSize(std::size_t n) { size_ = n; }
  std::size_t capacity() const { return capacity_; }

 private:
  void grow(std::size_t more) {
    std::size_t next = capacity_ < 4096 ? 4096 : capacity_ * 2;
    while (next - size_ < more)
      next *= 2;
    auto bigger = std::make_unique_for_overwrite<char[]>(next);
    if (size_ > 0) std::memcpy(bigger.get(), data_.get(), size_);
    data_ = std::move(bigger);
    capacity_ = next;
  }

  std::unique_ptr<char[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

// Appends to a Buffer through a cursor; the buffer's size is set when the appender goes (or on
// flush()). Only one appender per buffer at a time, and no other writes while it lives.
class Appender {
 public:
  explicit Appender(Buffer& b)
      : buffer_(b), p_(b.data() + b.size()), end_(b.data() + b.capacity()) {}
  ~Appender() { flush(); }
  Appender(const Appender&) = delete;
  Appender& operator=(const Appender&) = delete;

  void flush() { buffer_.setSize(static_cast<std::size_t>(p_ - buffer_.data())); }
  std::size_t position() const { return static_cast<std::size_t>(p_ - buffer_.data()); }

  void room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - p_) < n) grow(n);
  }
  void put(char c) {
    room(1);
    *p_++ = c;
  }
  // A string literal, its length known at compile time.
  template <std::size_t N>
  void lit(const char (&s)[N]) {
    room(N - 1);
    std::memcpy(p_, s, N - 1);
    p_ += N - 1;
  }
  void text(std::string_view s) {
    room(s.size());
    std::memcpy(p_, s.data(), s.size());
    p_ += s.size();
  }
  void u16(std::uint16_t v) { le(v, 2); }
  void u32(std::uint32_t v) { le(v, 4); }
  void u64(std::uint64_t v) { le(v, 8); }

  // JSON: the shortest text that reads back as the same double; -0 is written "-0.0" so a reader
  // that takes "-0" for the integer 0 still keeps the sign.
  void number(double v) {
    if (v == 0.0) {
      if (std::signbit(v)) {
        lit("-0.0");
      } else {
        put('0');
      }
      return;
    }
    room(32);
    p_ = std::to_chars(p_, end_, v).ptr;
  }
  // A double in a fixed or general format with a precision (the viewer's rounded values).
  void number(double v, std::chars_format format, int precision) {
    room(48);
    const auto r = std::to_chars(p_, end_, v, format, precision);
    if (r.ec == std::errc()) {
      p_ = r.ptr;
    } else {
      lit("0");  // |v| beyond what 48 characters hold: not a pose of this program
    }
  }
  // v with at most `decimals` (<= 9) digits after the point, correctly rounded for the pose and
  // orientation a viewer draws, trailing zeros dropped ("1.5", "-0.25", "3").
  void fixed(double v, int decimals) {
    static constexpr double kScale[10] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    if (!(std::fabs(v) < 1e9) || decimals < 0 || decimals > 9) {
      number(v, std::chars_format::fixed, decimals < 0 || decimals > 9 ? 9 : decimals);
      return;
    }
    const long long scaled = std::llround(v * kScale[decimals]);
    auto magnitude = static_cast<std::uint64_t>(scaled < 0 ? -scaled : scaled);
    room(40);
    if (scaled < 0) *p_++ = '-';
    const auto unit = static_cast<std::uint64_t>(kScale[decimals]);
    p_ = std::to_chars(p_, end_, magnitude / unit).ptr;
    std::uint64_t frac = magnitude % unit;
    if (frac == 0) return;
    int digits = decimals;
    while (frac % 10 == 0) {
      frac /= 10;
      --digits;
    }
    *p_++ = '.';
    for (int i = digits - 1; i >= 0; --i) {
      p_[i] = static_cast<char>('0' + frac % 10);
      frac /= 10;
    }
    p_ += digits;
  }
  void integer(std::uint64_t v) {
    room(24);
    p_ = std::to_chars(p_, end_, v).ptr;
  }
  // A JSON string with the escapes it needs (the text is UTF-8 already).
  void string(std::string_view s) {
    room(6 * s.size() + 2);
    *p_++ = '"';
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '"' || c == '\\') {
        *p_++ = '\\';
        *p_++ = ch;
      } else if (c < 0x20) {
        static constexpr char kHex[] = "0123456789abcdef";
        std::memcpy(p_, "\\u00", 4);
        p_[4] = kHex[c >> 4];
        p_[5] = kHex[c & 15];
        p_ += 6;
      } else {
        *p_++ = ch;
      }
    }
    *p_++ = '"';
  }

 private:
  void le(std::uint64_t v, int n) {
    room(8);
    for (int i = 0; i < n; ++i)
      p_[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    p_ += n;
  }
  void grow(std::size_t n) {
    flush();
    buffer_.reserveMore(n);
    p_ = buffer_.data() + buffer_.size();
    end_ = buffer_.data() + buffer_.capacity();
  }

  Buffer& buffer_;
  char* p_;
  char* end_;
};

}  // namespace tactile::mcap
