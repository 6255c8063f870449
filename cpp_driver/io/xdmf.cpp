#include "io/xdmf.hpp"

#include <fmt/format.h>

#include "io/file_write.hpp"

namespace sphjet::xdmf {

namespace {

std::string escape(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

const char* number_type(NumberType t) { return t == NumberType::Float64 ? "Float" : "Int"; }
int precision(NumberType t) { return t == NumberType::Int32 ? 4 : 8; }

void data_item(std::string& out, const std::string& indent, const Grid& g,
               const std::string& dataset, NumberType t, bool vector) {
    const std::string dims = vector ? fmt::format("{} 3", g.n) : fmt::format("{}", g.n);
    out += fmt::format(
        "{}<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">"
        "{}:{}</DataItem>\n",
        indent, dims, number_type(t), precision(t), escape(g.h5_file), escape(dataset));
}

void collection(std::string& out, const Collection& c) {
    out += fmt::format("    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                       escape(c.name));
    const std::string i4(8, ' '), i5(10, ' ');
    for (const Grid& g : c.grids) {
        out += fmt::format("      <Grid Name=\"{}\" GridType=\"Uniform\">\n", escape(g.name));
        out += fmt::format("{}<Time Value=\"{:.17g}\"/>\n", i4, g.time);
        out += fmt::format(
            "{}<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" "
            "NodesPerElement=\"1\">\n",
            i4, g.n);
        data_item(out, i5, g, g.connectivity, NumberType::Int64, false);
        out += i4 + "</Topology>\n";
        out += i4 + "<Geometry GeometryType=\"XYZ\">\n";
        data_item(out, i5, g, g.points, NumberType::Float64, true);
        out += i4 + "</Geometry>\n";
        for (const Field& f : g.fields) {
            out += fmt::format("{}<Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n",
                               i4, escape(f.name), f.vector ? "Vector" : "Scalar");
            data_item(out, i5, g, f.dataset, f.type, f.vector);
            out += i4 + "</Attribute>\n";
        }
        out += "      </Grid>\n";
    }
    out += "    </Grid>\n";
}

}  // namespace

std::string document(std::span<const Collection> collections) {
    std::string out =
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
        "  <Domain>\n";
    for (const Collection& c : collections) collection(out, c);
    out +=
        "  </Domain>\n"
        "</Xdmf>\n";
    return out;
}

std::string document(std::span<const Grid> grids) {
    const Collection c{"particles", {grids.begin(), grids.end()}};
    return document(std::span<const Collection>(&c, 1));
}

void write(const std::filesystem::path& path, std::span<const Collection> collections) {
    write_file_atomically(path, document(collections), "the XDMF index");
}

void write(const std::filesystem::path& path, std::span<const Grid> grids) {
    write_file_atomically(path, document(grids), "the XDMF index");
}

}  // namespace sphjet::xdmf
