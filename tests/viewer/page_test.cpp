// The viewer page's contents without a browser: which edges are drawn as restored sharp edges,
// what the page stores, and that nothing in it can close its script elements early.

#include "viewer/page.h"

#include <gtest/gtest.h>

#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::viewer {
namespace {

/// A square on z = 0 (the input) and a pyramid over it whose apex is the one new point.
struct Pyramid {
    Mesh input;
    Mesh restored;
};

Pyramid pyramid(double height) {
    Pyramid p;
    p.input.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    p.input.triangles = {{0, 1, 2}, {0, 2, 3}};
    p.restored.positions = p.input.positions;
    p.restored.positions.push_back({0.5, 0.5, height});
    p.restored.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    return p;
}

TEST(SharpEdges, TheCreasesThroughANewPoint) {
    const Pyramid p = pyramid(1.0);  // neighbouring sides meet at about 78 degrees
    const auto edges = sharp_edges(p.input, p.restored);
    ASSERT_EQ(edges.size(), 4u);  // the open base edges are boundaries: never drawn
    for (const auto& edge : edges) EXPECT_TRUE(edge[0] == 4 || edge[1] == 4);
}

TEST(SharpEdges, NotWhereTheFacesLieNearlyFlat) {
    const Pyramid p = pyramid(0.02);  // sides meet at about 3.2 degrees
    EXPECT_TRUE(sharp_edges(p.input, p.restored).empty());
    EXPECT_EQ(sharp_edges(p.input, p.restored, 2.0).size(), 4u);
}

TEST(SharpEdges, NotBetweenInputVertices) {
    Pyramid p = pyramid(1.0);
    p.input.positions.push_back(p.restored.positions[4]);  // the apex was there before
    EXPECT_TRUE(sharp_edges(p.input, p.restored).empty());
}

std::string page_of(const PageContent& content) {
    std::ostringstream out;
    write_page(out, content);
    return out.str();
}

/// The text of the element with `id`, between its start tag's '>' and the next '<'.
std::string block(const std::string& page, const std::string& id) {
    const std::size_t at = page.find("id=\"" + id + "\">");
    if (at == std::string::npos) return "(missing)";
    const std::size_t start = page.find('>', at) + 1;
    return page.substr(start, page.find('<', start) - start);
}

TEST(ViewerPage, StoresTheSharedInputVerticesOnceAndEscapesTheTitle) {
    const Pyramid p = pyramid(1.0);
    const std::string page =
        page_of({.title = "</script><b>x", .input = &p.input, .restored = &p.restored});
    // Base64 of 4 x 3 floats (48 bytes) for the input, of the one new point (12 bytes) for the
    // restored mesh, of 4 x 3 indices (48 bytes) for its triangles, 4 x 2 for the sharp edges.
    EXPECT_EQ(block(page, "input-positions").size(), 64u);
    EXPECT_EQ(block(page, "restored-positions").size(), 16u);
    EXPECT_EQ(block(page, "restored-triangles").size(), 64u);
    EXPECT_EQ(block(page, "sharp-edges").size(), 44u);
    EXPECT_EQ(page.find("id=\"segment-roles\""), std::string::npos);
    EXPECT_EQ(page.find("</script><b>"), std::string::npos);
    EXPECT_NE(page.find("<title>&lt;/script&gt;&lt;b&gt;x - resharp</title>"), std::string::npos);
    EXPECT_NE(page.find("\"title\":\"<\\/script><b>x\""), std::string::npos);
    EXPECT_NE(page.find("Permission is hereby granted"), std::string::npos) << "licence kept";
    EXPECT_EQ(page.find("@SCRIPT@"), std::string::npos);
}

TEST(ViewerPage, FirstBytesOfAPositionBlockAreLittleEndianFloats) {
    Pyramid p = pyramid(1.0);
    p.input.positions[0] = {1.0, 0, 0};  // 1.0f is 00 00 80 3f: base64 "AACAPw"
    const std::string page = page_of({.input = &p.input, .restored = &p.restored});
    EXPECT_EQ(block(page, "input-positions").substr(0, 6), "AACAPw");
}

TEST(ViewerPage, SegmentsMustMatchTheInput) {
    const Pyramid p = pyramid(1.0);
    cli::SegmentLayers layers{.is_edge_vertex = {0, 1, 0, 0},
                              .face_role = {BandRole::Edge, BandRole::None},
                              .patch_color = {{1, 2, 3}, {4, 5, 6}}};
    const std::string page =
        page_of({.input = &p.input, .restored = &p.restored, .segments = &layers});
    EXPECT_EQ(block(page, "segment-roles"), "AQA=");  // bytes 01 00
    layers.face_role.pop_back();
    EXPECT_THROW(page_of({.input = &p.input, .restored = &p.restored, .segments = &layers}),
                 InvalidInput);
    EXPECT_THROW(page_of({.input = &p.input}), InvalidInput);
}

}  // namespace
}  // namespace resharp::viewer
