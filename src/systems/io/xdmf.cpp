#include "systems/io/xdmf.hpp"

#include <sstream>

namespace ryushi {

std::string xdmf_document(const std::vector<FrameRecord>& frames) {
  std::ostringstream out;
  out.precision(15);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (auto& f : frames) {
    const std::string n = std::to_string(f.particles);
    const std::string h5 = "Format=\"HDF\">" + f.file + ":/";
    // Explicit vertex connectivity: the legacy XDMF reader makes cells without it, the Xdmf3
    // readers (ParaView's default for .xdmf) do not and would draw an empty view.
    out << "   <Grid Name=\"frame\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << f.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n"
        << "     <DataItem Dimensions=\"" << n << " 1\" NumberType=\"Int\" Precision=\"4\" " << h5
        << "connectivity</DataItem>\n"
        << "    </Topology>\n"
        << "    <Geometry GeometryType=\"XYZ\">\n"
        << "     <DataItem Dimensions=\"" << n << " 3\" NumberType=\"Float\" Precision=\"8\" " << h5
        << "position</DataItem>\n"
        << "    </Geometry>\n";
    for (auto& field : f.fields) {
      if (field.name == "position") continue;
      // Frames store vectors as 3 and tensors as 3 x 3 components in 2D too (hdf5_frame.hpp).
      const char* type = "Scalar";
      const char* components = "";
      const char* number = "Float\" Precision=\"8";
      if (field.type == ColumnType::Vector) {
        type = "Vector";
        components = " 3";
      } else if (field.type == ColumnType::Tensor) {
        type = "Tensor";
        components = " 9";
      } else if (field.type == ColumnType::Flags) {
        number = "Int\" Precision=\"4";
      }
      out << "    <Attribute Name=\"" << field.name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n"
          << "     <DataItem Dimensions=\"" << n << components << "\" NumberType=\"" << number << "\" " << h5
          << field.name << "</DataItem>\n    </Attribute>\n";
    }
    out << "   </Grid>\n";
  }
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return out.str();
}

}  // namespace ryushi
