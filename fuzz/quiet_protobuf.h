#pragma once
// Included by the fuzz targets that parse protobuf (one per binary): libFuzzer
// calls this once before the first input. Protobuf logs every string field
// that is not UTF-8 to stderr; across millions of inputs that logging would
// cost more than the parsing it reports on, and it says nothing we check.
#include <google/protobuf/stubs/logging.h>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  google::protobuf::SetLogHandler(nullptr);
  return 0;
}
