// scripts/make_exr_samples.cpp -- writes the OpenEXR sample files of tests/data/exr with
// OpenEXR's own library (the outside writer the reader is tested against). A development
// tool, never built by make: tests/data/exr/README.md has the command.
//
// Every colour file holds the formula the tests recompute independently, at pixel (x, y)
// from the data window's top left:  R = x + 0.25 y,  G = -2.5,  B = 0.001 x y.
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfPartType.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfFrameBuffer.h>
#include <ImfTiledOutputFile.h>
#include <half.h>
#include <cstdint>
#include <string>
#include <vector>

using namespace Imf;
using namespace Imath;

static float formula(int c, int x, int y)
{
    return c == 0 ? x + 0.25f * y : c == 1 ? -2.5f : 0.001f * x * y;
}

// One image: channels named in names (R, G, B, A or Y), all of type t; Y and A hold
// 0.5 x + y and 0.75.
static void write(const std::string &file, int w, int h, PixelType t, Compression comp,
                  const std::vector<std::string> &names, LineOrder order = INCREASING_Y,
                  int x0 = 0, int y0 = 0)
{
    Box2i data(V2i(x0, y0), V2i(x0 + w - 1, y0 + h - 1));
    Header header(data, data);
    header.compression() = comp;
    header.lineOrder() = order;
    std::vector<std::vector<float>> f(names.size(), std::vector<float>(w * h));
    std::vector<std::vector<half>> hv(names.size(), std::vector<half>(w * h));
    std::vector<std::vector<uint32_t>> u(names.size(), std::vector<uint32_t>(w * h));
    FrameBuffer fb;
    for (size_t c = 0; c < names.size(); c++) {
        const std::string &n = names[c];
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                float v = n == "R" ? formula(0, x, y) : n == "G" ? formula(1, x, y)
                        : n == "B" ? formula(2, x, y) : n == "Y" ? 0.5f * x + y : 0.75f;
                f[c][y * w + x] = v;
                hv[c][y * w + x] = half(v);
                u[c][y * w + x] = (uint32_t)(x + 100 * y); // UINT: whole numbers
            }
        header.channels().insert(n, Channel(t));
        char *base = t == FLOAT ? (char *)f[c].data() : t == HALF ? (char *)hv[c].data()
                                                                  : (char *)u[c].data();
        size_t s = t == HALF ? 2 : 4;
        fb.insert(n, Slice(t, base - (x0 + (ptrdiff_t)y0 * w) * s, s, s * w));
    }
    OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

static void write_tiled(const std::string &file)
{
    Header header(5, 3);
    header.channels().insert("R", Channel(FLOAT));
    header.channels().insert("G", Channel(FLOAT));
    header.channels().insert("B", Channel(FLOAT));
    header.setTileDescription(TileDescription(4, 4));
    std::vector<float> p(15, 1.0f);
    FrameBuffer fb;
    for (const char *n : {"R", "G", "B"})
        fb.insert(n, Slice(FLOAT, (char *)p.data(), 4, 20));
    TiledOutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
}

static void write_multipart(const std::string &file)
{
    std::vector<Header> headers(2, Header(5, 3));
    std::vector<float> p(15, 1.0f);
    for (int i = 0; i < 2; i++) {
        headers[i].setName(i == 0 ? "left" : "right");
        headers[i].setType(SCANLINEIMAGE);
        headers[i].channels().insert("R", Channel(FLOAT));
        headers[i].channels().insert("G", Channel(FLOAT));
        headers[i].channels().insert("B", Channel(FLOAT));
    }
    MultiPartOutputFile out(file.c_str(), headers.data(), 2);
    for (int i = 0; i < 2; i++) {
        OutputPart part(out, i);
        FrameBuffer fb;
        for (const char *n : {"R", "G", "B"})
            fb.insert(n, Slice(FLOAT, (char *)p.data(), 4, 20));
        part.setFrameBuffer(fb);
        part.writePixels(3);
    }
}

// Y alone, HALF: the first row holds values at the edges of the half range (subnormals,
// the smallest normal, the largest finite, negative zero, values rounded on the way in),
// the other rows zero, so that deflate makes runs of its longest length (258).
static void write_special(const std::string &file)
{
    const float first[] = {5.9604645e-8f, -5.9604645e-8f, 1.7881393e-7f, 6.0975552e-5f,
                           6.1035156e-5f, 65504.0f, -0.0f, 0.1f, 1e-3f, 3.14159f, -65519.0f};
    const int w = 41, h = 16, n = sizeof first / sizeof first[0];
    Header header(w, h);
    header.compression() = ZIP_COMPRESSION;
    header.channels().insert("Y", Channel(HALF));
    std::vector<half> p(w * h, half(0.0f));
    for (int x = 0; x < n; x++)
        p[x] = half(first[x]);
    FrameBuffer fb;
    fb.insert("Y", Slice(HALF, (char *)p.data(), 2, 2 * w));
    OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

// FLOAT RGB whose words take more than 2^14 values, so that PIZ uses its 16-bit wavelet:
// channel c at (x, y) is ((x * 7919 + y * 104729 + c * 15485863) % 1000003) / 1024, exact
// in a float.
static void write_wide_piz(const std::string &file)
{
    const int w = 101, h = 67;
    Header header(w, h);
    header.compression() = PIZ_COMPRESSION;
    std::vector<float> p[3];
    FrameBuffer fb;
    const char *names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; c++) {
        p[c].resize(w * h);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                p[c][y * w + x] = (float)((x * 7919L + y * 104729L + c * 15485863L) % 1000003L) / 1024.0f;
        header.channels().insert(names[c], Channel(FLOAT));
        fb.insert(names[c], Slice(FLOAT, (char *)p[c].data(), 4, 4 * w));
    }
    OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

// Y alone, HALF, 1024 x 45, whose half at (x, y) has the bits 29 x + y: a smooth ramp of
// about 30,000 distinct words, so that PIZ compresses every block (the last one of 13 rows,
// odd) and uses its 16-bit wavelet.
static void write_ramp_piz(const std::string &file)
{
    const int w = 1024, h = 45;
    Header header(w, h);
    header.compression() = PIZ_COMPRESSION;
    header.channels().insert("Y", Channel(HALF));
    std::vector<half> p(w * h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            p[y * w + x].setBits((unsigned short)(29 * x + y));
    FrameBuffer fb;
    fb.insert("Y", Slice(HALF, (char *)p.data(), 2, 2 * w));
    OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

int main()
{
    write_ramp_piz("ramp-half-piz.exr");
    write_wide_piz("wide-float-piz.exr");
    write_special("y-half-special-zip.exr");
    const std::vector<std::string> rgb = {"R", "G", "B"}, rgba = {"R", "G", "B", "A"};
    const struct { Compression c; const char *name; } comps[] = {
        {NO_COMPRESSION, "none"}, {RLE_COMPRESSION, "rle"}, {ZIPS_COMPRESSION, "zips"},
        {ZIP_COMPRESSION, "zip"}, {PIZ_COMPRESSION, "piz"}};
    for (auto &c : comps) {
        write(std::string("half-") + c.name + ".exr", 7, 5, HALF, c.c, rgb);
        write(std::string("float-") + c.name + ".exr", 7, 5, FLOAT, c.c, rgb);
        // Many rows and blocks, the last one short; the values repeat enough to compress.
        write(std::string("large-half-") + c.name + ".exr", 61, 37, HALF, c.c, rgba);
    }
    write("rgba-half-zip.exr", 7, 5, HALF, ZIP_COMPRESSION, rgba);
    write("y-half-zip.exr", 7, 5, HALF, ZIP_COMPRESSION, {"Y"});
    write("uint-none.exr", 7, 5, UINT, NO_COMPRESSION, rgb);
    write("decreasing-float-zip.exr", 7, 37, FLOAT, ZIP_COMPRESSION, rgb, DECREASING_Y);
    write("window-half-rle.exr", 7, 5, HALF, RLE_COMPRESSION, rgb, INCREASING_Y, 3, -2);
    write("pxr24.exr", 7, 5, FLOAT, PXR24_COMPRESSION, rgb);
    write_tiled("tiled.exr");
    write_multipart("multipart.exr");
    return 0;
}
