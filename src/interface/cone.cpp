#include "rccm/interface/cone.hpp"

namespace rccm {

const char* status_name(Status s) {
  switch (s) {
    case Status::Separated: return "separated";
    case Status::Stick: return "stick";
    case Status::Slide: return "slide";
  }
  return "";
}

}  // namespace rccm
