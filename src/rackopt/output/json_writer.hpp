// A small streaming JSON writer: enough for our reports (objects, arrays,
// numbers, strings, booleans). Non-finite numbers are written as null so the
// output always parses. Keys are written in the order given.
#pragma once

#include <string>
#include <vector>

namespace rackopt {

class JsonWriter {
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(const std::string& k);
  JsonWriter& value(double v);
  JsonWriter& value(int v);
  JsonWriter& value(long v);
  JsonWriter& value(bool v);
  JsonWriter& value(const std::string& v);
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& null();
  // A value that is already JSON text (one complete value, e.g. an object
  // another writer produced), inserted as is.
  JsonWriter& raw(const std::string& json_value);
  const std::string& str() const { return out_; }

  static std::string escape(const std::string& s);

 private:
  void separator();
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written yet
  bool after_key_ = false;
};

}  // namespace rackopt
