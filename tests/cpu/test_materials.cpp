// CPU tier: OBJ material libraries, vertex colours and texture coordinates through the loader
// (obj_parser, mtl_parser, polygon_soup): every statement, and every bad input a warning that
// names the file and line while the model still loads.
#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/core/image_io.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/opacity_map.h"
#include "renderer/mesh/texture_average.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

bool anyWarning(const Mesh& m, const std::string& needle) {
  return std::any_of(m.report.warnings.begin(), m.report.warnings.end(), [&](const std::string& w) { return w.find(needle) != std::string::npos; });
}

const MeshMaterial* material(const Mesh& m, const std::string& name) {
  for (const MeshMaterial& x : m.materials)
    if (x.name == name) return &x;
  return nullptr;
}

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(Materials, EveryStatementReachesTheMaterial) {
  TempDir d;
  d.write("a.mtl",
          "# comment\nnewmtl shiny\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nKe 0.01 0.02 0.03\nNs 250\nd 0.5\nillum 2\n"
          "Ni 1.5\nTf 1 1 1\nbump foo.png\nPr 0.3\n"  // unknown to GL's model: ignored
          "newmtl grey\nKd 0.25\nTr 0.2\nNs 10\n"
          "newmtl flat\nKd 0.3 0.6 0.9\nKs 1 1 1\nNs 30\nillum 0\n"
          "newmtl matte\nKs 1 1 1\nNs 30\nillum 1\n"
          "newmtl dull\nKs 1 1 1\nNs 0\n");
  auto m = loadMesh(d.write("a.obj", std::string("mtllib a.mtl\n") + kQuad +
                                         "usemtl shiny\nf 1 2 3\nusemtl grey\nf 1 3 4\nusemtl flat\nf 1 2 4\nusemtl matte\nf 2 3 4\nusemtl dull\nf 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.materials, 5u);
  EXPECT_TRUE(m->report.warnings.empty()) << m->report.toJson();
  const MeshMaterial* s = material(*m, "shiny");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->ambient, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(s->diffuse, glm::vec3(0.4f, 0.5f, 0.6f));
  EXPECT_EQ(s->specular, glm::vec3(0.7f, 0.8f, 0.9f));
  EXPECT_EQ(s->emission, glm::vec3(0.01f, 0.02f, 0.03f));
  EXPECT_EQ(s->shininess, 128.0f);  // Ns 250 clamped to GL's range
  EXPECT_EQ(s->opacity, 0.5f);
  const MeshMaterial* g = material(*m, "grey");
  EXPECT_EQ(g->diffuse, glm::vec3(0.25f));  // one number: grey
  EXPECT_FLOAT_EQ(g->opacity, 0.8f);        // Tr is 1 - d
  const MeshMaterial* f = material(*m, "flat");  // illum 0: the diffuse colour, unlit
  EXPECT_EQ(f->emission, glm::vec3(0.3f, 0.6f, 0.9f));
  EXPECT_EQ(f->diffuse, glm::vec3(0.0f));
  EXPECT_EQ(f->specular, glm::vec3(0.0f));
  EXPECT_EQ(material(*m, "matte")->specular, glm::vec3(0.0f));  // illum 1: no highlight
  EXPECT_EQ(material(*m, "dull")->specular, glm::vec3(0.0f));   // Ns 0: no highlight
  // Faces keep their material through loading, in file order.
  ASSERT_EQ(m->faceMaterials.size(), 5u);
  std::vector<std::string> names;
  for (std::uint16_t i : m->faceMaterials) names.push_back(m->materials[i].name);
  EXPECT_EQ(names, (std::vector<std::string>{"shiny", "grey", "flat", "matte", "dull"}));
}

TEST(Materials, UsemtlBeforeMtllibAndSeveralLibraries) {
  TempDir d;
  d.write("one.mtl", "newmtl a\nKd 1 0 0\n");
  d.write("two.mtl", "newmtl b\nKd 0 1 0\n");
  auto m = loadMesh(d.write("x.obj", std::string(kQuad) + "usemtl b\nf 1 2 3\nusemtl a\nf 1 3 4\nmtllib one.mtl two.mtl\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.material_libraries.size(), 2u);
  EXPECT_EQ(material(*m, "a")->diffuse, glm::vec3(1, 0, 0));
  EXPECT_EQ(material(*m, "b")->diffuse, glm::vec3(0, 1, 0));
  EXPECT_FALSE(material(*m, "b")->fromLightingState);
}

TEST(Materials, NamesWithSpacesAndBackslashes) {
  TempDir d;
  std::filesystem::create_directories(d.path() / "maps");
  ASSERT_TRUE(writeImage((d.path() / "maps" / "wood grain.png").string(), ImageRGBA8{2, 2, std::vector<std::uint8_t>(16, 200)}));
  d.write("my materials.mtl", "newmtl wood\nmap_Kd -o 0 0 -clamp off .\\maps\\wood grain.png\n");
  auto m = loadMesh(d.write("x.obj", std::string("mtllib my materials.mtl\n") + kQuad + "vt 0 0\nvt 1 0\nvt 1 1\nusemtl wood\nf 1/1 2/2 3/3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_TRUE(m->report.warnings.empty()) << m->report.toJson();
  ASSERT_EQ(m->report.textures_loaded.size(), 1u);
  EXPECT_NE(m->report.textures_loaded[0].find("wood grain.png"), std::string::npos);
  EXPECT_EQ(material(*m, "wood")->diffuseMap, 0);
  ASSERT_EQ(m->faceTints.size(), 1u);
  EXPECT_NEAR(m->faceTints[0].r, 200.0f / 255.0f, 1e-3f);
}

// Maps are reduced while they are read (what a hostile .mtl naming many huge images can cost
// is bounded: 64 maps of at most 1024 a side).
TEST(Materials, LargeMapsAreReducedWhileRead) {
  TempDir d;
  ASSERT_TRUE(writeImage((d.path() / "wide.png").string(), ImageRGBA8{1500, 6, std::vector<std::uint8_t>(1500 * 6 * 4, 128)}));
  d.write("m.mtl", "newmtl a\nmap_Kd wide.png\n");
  auto m = loadMesh(d.write("x.obj", std::string("mtllib m.mtl\n") + kQuad + "vt 0 0\nusemtl a\nf 1/1 2/1 3/1\n"));
  ASSERT_TRUE(m) << m.error();
  ASSERT_EQ(m->textures.size(), 1u);
  EXPECT_LE(m->textures[0].image.width, 1024);
  EXPECT_GE(m->textures[0].image.width, 512);
}

TEST(Materials, MissingAndBrokenFilesAreWarningsNamingFileAndLine) {
  TempDir d;
  d.write("broken.png", "not a png at all");
  d.write("m.mtl", "Kd 1 1 1\nnewmtl a\nKd one two\nmap_Kd nowhere.png\nnewmtl b\nmap_Kd broken.png\nmap_Kd\n");
  auto m = loadMesh(d.write("x.obj", std::string("mtllib missing.mtl\nmtllib m.mtl\n") + kQuad +
                                         "vt 0 0\nusemtl a\nf 1/1 2/1 3/1\nusemtl b\nf 1/1 3/1 4/1\nusemtl ghost\nf 1 2 4\n"));
  ASSERT_TRUE(m) << m.error();  // never a failure: the faces keep the default material
  EXPECT_EQ(m->triangleCount(), 3u);
  EXPECT_TRUE(anyWarning(*m, "x.obj line 1: material library 'missing.mtl' cannot be read")) << m->report.toJson();
  EXPECT_TRUE(anyWarning(*m, "m.mtl line 1: 'Kd' before any newmtl"));
  EXPECT_TRUE(anyWarning(*m, "m.mtl line 3: Kd needs 1 or 3 numbers"));
  EXPECT_TRUE(anyWarning(*m, "m.mtl line 2: texture map cannot be used"));  // the material's newmtl line
  EXPECT_TRUE(anyWarning(*m, "m.mtl line 7: map_Kd without a file name"));
  EXPECT_TRUE(anyWarning(*m, "x.obj line 12: material 'ghost' is not defined"));
  EXPECT_EQ(m->report.textures_missing.size(), 2u);
  EXPECT_TRUE(material(*m, "ghost")->fromLightingState);
  EXPECT_EQ(material(*m, "a")->diffuseMap, -1);
  EXPECT_EQ(material(*m, "a")->diffuse, glm::vec3(0.8f));  // the malformed Kd left the default
}

TEST(Materials, VertexColoursAndTextureCoordinatesSurviveTriangulation) {
  TempDir d;
  // A concave pentagon (ear-clipped) with a colour and a texture coordinate per corner.
  auto m = loadMesh(d.write("c.obj",
                            "v 0 0 0 1 0 0\nv 2 0 0 0 1 0\nv 2 2 0 0 0 1\nv 1 0.5 0 1 1 0\nv 0 2 0 0 1 1\n"
                            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.25\nvt 0 1\nf 1/1 2/2 3/3 4/4 5/5\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_TRUE(m->report.vertex_colours);
  EXPECT_TRUE(m->report.texture_coordinates);
  EXPECT_EQ(m->triangleCount(), 3u);
  ASSERT_EQ(m->colours.size(), m->positions.size());
  ASSERT_EQ(m->texcoords.size(), m->positions.size());
  // Every vertex keeps the colour and coordinate of the file vertex at its position.
  const glm::vec3 colourAt[5] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}};
  const glm::vec2 uvAt[5] = {{0, 0}, {1, 0}, {1, 1}, {0.5f, 0.25f}, {0, 1}};
  const glm::vec3 rawAt[5] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5f, 0}, {0, 2, 0}};
  for (std::size_t i = 0; i < m->positions.size(); ++i) {
    const glm::dvec3 raw = glm::dvec3(m->positions[i]) / m->report.original_scale + m->report.original_centre;
    int k = -1;
    for (int j = 0; j < 5; ++j)
      if (glm::length(raw - glm::dvec3(rawAt[j])) < 1e-4) k = j;
    ASSERT_GE(k, 0);
    EXPECT_EQ(m->colours[i], colourAt[k]);
    EXPECT_EQ(m->texcoords[i], uvAt[k]);
  }
}

TEST(Materials, SplitVerticesShareNormalsAndRefusedFacesKeepTheirAttributes) {
  TempDir d;
  d.write("m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 0 1\n");
  // Two triangles of different materials share an edge (the vertices are split, normals
  // shared); a third repeats the first, which the halfedge structure refuses (copied).
  auto m = loadMesh(d.write("x.obj", std::string("mtllib m.mtl\n") + "v 0 0 0 1 0 0\nv 1 0 0.2\nv 1 1 0\nv 0 1 0.3\n" +
                                         "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\nusemtl a\nf 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.non_manifold_faces, 1u);
  ASSERT_EQ(m->faceMaterials.size(), 3u);
  EXPECT_EQ(m->materials[m->faceMaterials[0]].name, "a");
  EXPECT_EQ(m->materials[m->faceMaterials[1]].name, "b");
  EXPECT_EQ(m->materials[m->faceMaterials[2]].name, "a");
  // Vertex 1 of the file appears once per material, and both copies have one normal.
  std::vector<std::size_t> ofFirst;
  for (std::size_t i = 0; i < m->positions.size(); ++i)
    if (m->colours[i] == glm::vec3(1, 0, 0)) ofFirst.push_back(i);
  ASSERT_GE(ofFirst.size(), 2u);
  EXPECT_EQ(m->normals[ofFirst[0]], m->normals[ofFirst[1]]);
  for (std::size_t f = 0; f < 3; ++f)
    for (int k = 0; k < 3; ++k) EXPECT_LT(m->indices[f * 3 + std::size_t(k)], m->colours.size());
}

TEST(Materials, TextureAverageOverATriangle) {
  // Left half black, right half white: a triangle on the right averages white, one across
  // the middle grey.
  ImageRGBA8 img{64, 64, std::vector<std::uint8_t>(64 * 64 * 4, 255)};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) img.pixels[(std::size_t(y) * 64 + x) * 4 + std::size_t(c)] = 0;
  const TextureAverager avg(img);
  EXPECT_NEAR(avg.average({0.6f, 0.1f}, {0.9f, 0.1f}, {0.8f, 0.9f}).r, 1.0f, 0.05f);
  EXPECT_NEAR(avg.average({0.1f, 0.1f}, {0.4f, 0.1f}, {0.2f, 0.9f}).r, 0.0f, 0.05f);
  EXPECT_NEAR(avg.average({0.0f, 0.0f}, {1.0f, 0.0f}, {0.5f, 1.0f}).r, 0.5f, 0.1f);
  EXPECT_NEAR(avg.whole().r, 0.5f, 1e-3f);
  // Non-finite coordinates fall back to the whole map, never NaN.
  EXPECT_NEAR(avg.average({NAN, 0.0f}, {1.0f, 0.0f}, {0.5f, 1.0f}).r, 0.5f, 1e-3f);
}


// A see-through material's per-triangle tint (what the per-triangle paths light it with) is the
// colour of the texels drawn, weighted by alpha: a map whose transparent half is red and opaque
// half blue tints both faces of a square over it blue; on an opaque material, each face takes
// the half it mostly lies on.
TEST(Materials, ASeeThroughMaterialsTintWeighsItsMapByAlpha) {
  Mesh m = test::square(1);
  for (const glm::vec3& p : m.positions) m.texcoords.push_back(glm::vec2(p.x * 0.5f + 0.5f, p.y * 0.5f + 0.5f));
  ImageRGBA8 map{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* px = &map.pixels[(std::size_t(y) * 16 + x) * 4];
      px[0] = x < 8 ? 255 : 0, px[1] = 0, px[2] = x < 8 ? 0 : 255, px[3] = x < 8 ? 0 : 255;
    }
  m.textures.push_back({"half.png", map});
  m.materials.resize(1);
  m.materials[0].diffuseMap = 0;
  m.faceMaterials.assign(m.triangleCount(), 0);
  for (MeshMaterial::Alpha alpha : {MeshMaterial::Alpha::Opaque, MeshMaterial::Alpha::Mask, MeshMaterial::Alpha::Blend}) {
    m.materials[0].alpha = alpha;
    computeFaceTints(m);
    ASSERT_EQ(m.faceTints.size(), m.triangleCount());
    const glm::vec3 mean = (m.faceTints[0] + m.faceTints[1]) / 2.0f;  // one face mostly on each half
    if (alpha == MeshMaterial::Alpha::Opaque) {
      EXPECT_NEAR(mean.r, 0.5f, 0.01f);  // both halves count
      EXPECT_NEAR(mean.b, 0.5f, 0.01f);
    }
    for (const glm::vec3& t : m.faceTints) {
      if (alpha != MeshMaterial::Alpha::Opaque) {
        EXPECT_LT(t.r, 0.02f) << "the cut-away red counts";
        EXPECT_GT(t.b, 0.98f);
      }
    }
  }
  // Wholly cut away: white (nothing of it shows), not black or NaN.
  TextureAverager none(ImageRGBA8{2, 2, std::vector<std::uint8_t>(16, 0)}, true);
  EXPECT_EQ(none.whole(), glm::vec3(1.0f));
}

// MTL transparency, read as Blender's importer reads it: d (or 1 - Tr) and map_d are the
// surface's alpha, drawn as screen-door transparency; map_d is folded into the diffuse map's
// alpha (the one map the renderer's coverage reads), the maps apart are not kept; a material
// with no opacity at all and no map (Tr 1, written the other way round) is drawn opaque with a
// warning naming the file and line.
TEST(Materials, DAndTrAndMapDBecomeTheSurfacesAlpha) {
  TempDir d;
  ImageRGBA8 red{4, 2, std::vector<std::uint8_t>(4 * 2 * 4, 255)};
  for (std::size_t i = 0; i < red.pixels.size(); i += 4) red.pixels[i + 1] = red.pixels[i + 2] = 0;
  ASSERT_TRUE(writeImage((d.path() / "leaf.png").string(), red));
  // Grey, no alpha: black on the left, white on the right.
  ImageRGBA8 mask{2, 1, {0, 0, 0, 255, 255, 255, 255, 255}};
  ASSERT_TRUE(writeImage((d.path() / "mask.png").string(), mask));
  d.write("t.mtl",
          "newmtl glass\nd 0.3\n"
          "newmtl solid\nd 1\n"
          "newmtl inverted\nTr 1\n"
          "newmtl leaf\nmap_Kd leaf.png\nmap_d mask.png\n"
          "newmtl cutout\nmap_d mask.png\n");
  auto m = loadMesh(d.write("t.obj", std::string("mtllib t.mtl\n") + kQuad +
                                         "vt 0 0\nvt 1 0\nvt 1 1\nusemtl glass\nf 1/1 2/2 3/3\nusemtl solid\nf 1/1 3/3 4/1\n"
                                         "usemtl inverted\nf 1/1 2/2 4/1\nusemtl leaf\nf 2/2 3/3 4/1\nusemtl cutout\nf 1/1 2/2 3/3\n"));
  ASSERT_TRUE(m) << m.error();
  const MeshMaterial* glass = material(*m, "glass");
  ASSERT_TRUE(glass);
  EXPECT_EQ(glass->alpha, MeshMaterial::Alpha::Blend);
  EXPECT_FLOAT_EQ(glass->opacity, 0.3f);
  EXPECT_EQ(material(*m, "solid")->alpha, MeshMaterial::Alpha::Opaque);
  const MeshMaterial* inverted = material(*m, "inverted");
  EXPECT_EQ(inverted->alpha, MeshMaterial::Alpha::Opaque);
  EXPECT_EQ(inverted->opacity, 1.0f);
  EXPECT_TRUE(anyWarning(*m, "t.mtl line 5: material 'inverted' is wholly transparent")) << m->report.toJson();
  // The leaf's map: its red, with the mask's grey as alpha (the mask stretched over it).
  const MeshMaterial* leaf = material(*m, "leaf");
  EXPECT_EQ(leaf->alpha, MeshMaterial::Alpha::Blend);
  ASSERT_GE(leaf->diffuseMap, 0);
  EXPECT_EQ(leaf->opacityMap, -1);
  const ImageRGBA8& folded = m->textures[std::size_t(leaf->diffuseMap)].image;
  ASSERT_EQ(folded.width, 4);
  ASSERT_EQ(folded.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      const std::uint8_t* px = &folded.pixels[(std::size_t(y) * 4 + std::size_t(x)) * 4];
      EXPECT_EQ(px[0], 255);
      EXPECT_EQ(px[1], 0);
      EXPECT_EQ(px[3], x < 2 ? 0 : 255) << x << "," << y;
    }
  // map_d alone: white, the mask as alpha, at the mask's size.
  const MeshMaterial* cutout = material(*m, "cutout");
  ASSERT_GE(cutout->diffuseMap, 0);
  const ImageRGBA8& white = m->textures[std::size_t(cutout->diffuseMap)].image;
  ASSERT_EQ(white.width, 2);
  EXPECT_EQ(white.pixels, (std::vector<std::uint8_t>{255, 255, 255, 0, 255, 255, 255, 255}));
  // Only the folded maps are kept for drawing, not leaf.png and mask.png apart.
  EXPECT_EQ(m->textures.size(), 2u);
  EXPECT_TRUE(m->seeThrough);
}

// Folding an opacity map into a colour map of another size, or none, or an empty one: every
// texel of the result is written from the opacity texel under it; nothing is read outside
// either image (the sanitizer tier runs this).
TEST(Materials, OpacityMapsFoldIntoColourMapsOfAnySize) {
  const ImageRGBA8 grey{1, 5, std::vector<std::uint8_t>(1 * 5 * 4, 128)};  // opaque mid grey
  const ImageRGBA8 colour{3, 1, std::vector<std::uint8_t>(3 * 1 * 4, 255)};
  const ImageRGBA8 a = withOpacityMap(&colour, grey);
  ASSERT_EQ(a.width, 3);
  ASSERT_EQ(a.height, 1);
  for (int x = 0; x < 3; ++x) EXPECT_EQ(a.pixels[std::size_t(x) * 4 + 3], 128);
  const ImageRGBA8 b = withOpacityMap(nullptr, grey);  // no colour map: white at the mask's size
  EXPECT_EQ(b.width, 1);
  EXPECT_EQ(b.height, 5);
  EXPECT_EQ(b.pixels[0], 255);
  EXPECT_EQ(b.pixels[3], 128);
  const ImageRGBA8 empty;
  EXPECT_EQ(withOpacityMap(&colour, empty).pixels, colour.pixels);  // nothing to fold
  EXPECT_EQ(withOpacityMap(&empty, grey).width, 1);                 // an empty colour map is none
}

}  // namespace
}  // namespace npr
