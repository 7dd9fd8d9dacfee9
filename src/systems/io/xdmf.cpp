#include "systems/io/xdmf.hpp"

#include <sstream>

namespace ryushi {

std::string xdmf_document(int D, const std::vector<FrameRecord>& frames) {
  std::ostringstream out;
  out.precision(12);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (auto& f : frames) {
    out << "   <Grid Name=\"frame\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << f.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.particles << "\"/>\n"
        << "    <Geometry GeometryType=\"" << (D == 2 ? "XY" : "XYZ") << "\">\n"
        << "     <DataItem Dimensions=\"" << f.particles << " " << D
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << f.file << ":/position</DataItem>\n"
        << "    </Geometry>\n";
    for (auto& field : f.fields) {
      if (field.name == "position") continue;
      const char* type = "Scalar";
      // Appended piecewise: GCC 12 reports a false -Wrestrict on `" " + std::to_string(..)`.
      std::string dims = std::to_string(f.particles);
      std::string number = "Float\" Precision=\"8";
      if (field.type == ColumnType::Vector) {
        type = "Vector";
        dims.append(" ").append(std::to_string(D));
      } else if (field.type == ColumnType::Tensor) {
        type = "Tensor";
        dims.append(" ").append(std::to_string(D * D));
      } else if (field.type == ColumnType::Flags) {
        number = "Int\" Precision=\"4";
      }
      // ParaView expects 3-component vectors; 2D vectors are still readable as 2-tuples.
      out << "    <Attribute Name=\"" << field.name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n"
          << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << number << "\" Format=\"HDF\">"
          << f.file << ":/" << field.name << "</DataItem>\n    </Attribute>\n";
    }
    out << "   </Grid>\n";
  }
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return out.str();
}

}  // namespace ryushi
