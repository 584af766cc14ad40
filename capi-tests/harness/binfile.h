// Record files of the differential harness: a sequence of named, typed arrays.
//
// File layout: "RJH1", then per record: u32 name length, name, u8 type, u64 byte count, bytes.
// Types: 'd' mjtNum, 'q' mjtNum quaternions (compared up to sign), 'f' float, 'i' int,
// 'b' byte, 'c' char, 's' self-check residual (each side must stay under the tolerance),
// 'r' raw bytes and 'o' offsets (used to rebuild a model, never compared).
// A record name is "quantity#instance": results are aggregated per quantity.

#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <sys/types.h>
#include <string>
#include <vector>

struct Rec {
  std::string name;
  char type = 'd';
  std::vector<unsigned char> bytes;

  size_t count() const {
    switch (type) {
      case 'd': case 'q': case 's': return bytes.size() / 8;
      case 'o': return bytes.size() / 8;
      case 'f': case 'i': return bytes.size() / 4;
      default: return bytes.size();
    }
  }
  const double* d() const { return reinterpret_cast<const double*>(bytes.data()); }
  const float* f() const { return reinterpret_cast<const float*>(bytes.data()); }
  const int* i() const { return reinterpret_cast<const int*>(bytes.data()); }
  const int64_t* o() const { return reinterpret_cast<const int64_t*>(bytes.data()); }
};

class Writer {
 public:
  void raw(const std::string& name, char type, const void* p, size_t nbytes) {
    Rec r;
    r.name = name;
    r.type = type;
    r.bytes.assign(static_cast<const unsigned char*>(p), static_cast<const unsigned char*>(p) + nbytes);
    recs_.push_back(std::move(r));
  }
  void d(const std::string& n, const double* p, size_t c) { raw(n, 'd', p, 8 * c); }
  void q(const std::string& n, const double* p, size_t c) { raw(n, 'q', p, 8 * c); }
  void f(const std::string& n, const float* p, size_t c) { raw(n, 'f', p, 4 * c); }
  void i(const std::string& n, const int* p, size_t c) { raw(n, 'i', p, 4 * c); }
  void i1(const std::string& n, int v) { raw(n, 'i', &v, 4); }
  void d1(const std::string& n, double v) { raw(n, 'd', &v, 8); }
  void s1(const std::string& n, double v) { raw(n, 's', &v, 8); }
  void str(const std::string& n, const char* s) {
    std::string t = s ? std::string(s) : std::string("(null)");
    raw(n, 'c', t.data(), t.size());
  }

  bool save(const std::string& path) const {
    FILE* fp = std::fopen(path.c_str(), "wb");
    if (!fp) return false;
    std::fwrite("RJH1", 1, 4, fp);
    for (const Rec& r : recs_) {
      uint32_t nl = r.name.size();
      uint64_t nb = r.bytes.size();
      std::fwrite(&nl, 4, 1, fp);
      std::fwrite(r.name.data(), 1, nl, fp);
      std::fwrite(&r.type, 1, 1, fp);
      std::fwrite(&nb, 8, 1, fp);
      if (nb) std::fwrite(r.bytes.data(), 1, nb, fp);
    }
    return std::fclose(fp) == 0;
  }

 private:
  std::vector<Rec> recs_;
};

// A record file read one record at a time (comparisons of large models: a file can exceed
// memory). open() indexes names, types and byte ranges; fetch() reads one record's bytes.
class IndexedReader {
 public:
  IndexedReader() = default;
  IndexedReader(const IndexedReader&) = delete;
  IndexedReader& operator=(const IndexedReader&) = delete;
  ~IndexedReader() {
    if (fp_) std::fclose(fp_);
  }

  bool open(const std::string& path) {
    fp_ = std::fopen(path.c_str(), "rb");
    if (!fp_) return false;
    char magic[4];
    bool ok = std::fread(magic, 1, 4, fp_) == 4 && !std::memcmp(magic, "RJH1", 4);
    while (ok) {
      uint32_t nl;
      if (std::fread(&nl, 4, 1, fp_) != 1) break;
      std::string name(nl, '\0');
      Ent e;
      ok = std::fread(&name[0], 1, nl, fp_) == nl && std::fread(&e.type, 1, 1, fp_) == 1 &&
           std::fread(&e.size, 8, 1, fp_) == 1;
      if (!ok) break;
      e.off = ftello(fp_);
      ok = e.off >= 0 && fseeko(fp_, static_cast<off_t>(e.size), SEEK_CUR) == 0;
      if (ok) {
        if (!index_.count(name)) order_.push_back(name);
        index_[name] = e;
      }
    }
    return ok;
  }

  // The names in file order.
  const std::vector<std::string>& names() const { return order_; }

  // Reads record `name` into r; false when absent or unreadable.
  bool fetch(const std::string& name, Rec& r) {
    auto it = index_.find(name);
    if (it == index_.end()) return false;
    const Ent& e = it->second;
    r.name = name;
    r.type = e.type;
    r.bytes.resize(e.size);
    return fseeko(fp_, e.off, SEEK_SET) == 0 &&
           (!e.size || std::fread(r.bytes.data(), 1, e.size, fp_) == e.size);
  }

 private:
  struct Ent {
    char type = 'd';
    uint64_t size = 0;
    off_t off = 0;
  };
  FILE* fp_ = nullptr;
  std::map<std::string, Ent> index_;
  std::vector<std::string> order_;
};

// A whole record file in memory.
class Reader {
 public:
  bool load(const std::string& path) {
    IndexedReader f;
    bool ok = f.open(path);
    for (const std::string& name : f.names()) {
      Rec r;
      if (!f.fetch(name, r)) return false;
      index_[name] = recs.size();
      recs.push_back(std::move(r));
    }
    return ok;
  }
  const Rec* get(const std::string& name) const {
    auto it = index_.find(name);
    return it == index_.end() ? nullptr : &recs[it->second];
  }
  // copies a record into p when it holds exactly nbytes
  bool copy(const std::string& name, void* p, size_t nbytes) const {
    const Rec* r = get(name);
    if (!r || r->bytes.size() != nbytes) return false;
    if (nbytes) std::memcpy(p, r->bytes.data(), nbytes);
    return true;
  }

  std::vector<Rec> recs;

 private:
  std::map<std::string, size_t> index_;
};
