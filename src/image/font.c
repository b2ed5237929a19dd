/*
 * image/font.c -- the glyphs of font.h, drawn by hand on a 5 x 7 grid ('#' inked), the
 * size of the classic dot-matrix character cells: the smallest in which every digit
 * stays unmistakable ('0' has a stroke across, so it is no 'O'; '1' a foot).
 * Only what the scale labels need is here: a label is a number as false_colour.c
 * formats it ("0.25", "1.5e-3", "12%"), and "p99" for a range that ends at a percentile.
 */
#include "font.h"

#include <string.h>

struct glyph {
    char c;
    const char *rows[FONT_HEIGHT];
};

static const struct glyph glyphs[] = {
    {'0', {" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "}},
    {'1', {"  #  ", " ##  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
    {'2', {" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"}},
    {'3', {"#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "}},
    {'4', {"   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "}},
    {'5', {"#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "}},
    {'6', {"  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "}},
    {'7', {"#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "}},
    {'8', {" ### ", "#   #", "#   #", " ### ", "#   #", "#   #", " ### "}},
    {'9', {" ### ", "#   #", "#   #", " ####", "    #", "   # ", " ##  "}},
    {'.', {"     ", "     ", "     ", "     ", "     ", " ##  ", " ##  "}},
    {'e', {"     ", "     ", " ### ", "#   #", "#####", "#    ", " ### "}},
    {'-', {"     ", "     ", "     ", " ### ", "     ", "     ", "     "}},
    {'+', {"     ", "  #  ", "  #  ", "#####", "  #  ", "  #  ", "     "}},
    {'%', {"##   ", "##  #", "   # ", "  #  ", " #   ", "#  ##", "   ##"}},
    {'p', {"     ", "     ", "#### ", "#   #", "#### ", "#    ", "#    "}},
    {' ', {"     ", "     ", "     ", "     ", "     ", "     ", "     "}},
};
#define N_GLYPHS (sizeof glyphs / sizeof glyphs[0])

static const struct glyph *find(char c)
{
    for (size_t i = 0; i < N_GLYPHS; i++)
        if (glyphs[i].c == c)
            return &glyphs[i];
    return NULL;
}

int font_has(char c)
{
    return c != '\0' && find(c) != NULL;
}

int font_pixel(char c, int x, int y)
{
    const struct glyph *g = find(c);
    return g == NULL || g->rows[y][x] == '#';
}

int font_text_width(const char *text, int scale)
{
    size_t n = strlen(text);
    return n == 0 ? 0 : ((int)n * FONT_ADVANCE - (FONT_ADVANCE - FONT_WIDTH)) * scale;
}

void font_draw(unsigned char *rgb, int width, int height, int x, int y, int scale,
               const char *text, const unsigned char colour[3])
{
    for (int i = 0; text[i] != '\0'; i++)
        for (int gy = 0; gy < FONT_HEIGHT; gy++)
            for (int gx = 0; gx < FONT_WIDTH; gx++) {
                if (!font_pixel(text[i], gx, gy))
                    continue;
                int x0 = x + (i * FONT_ADVANCE + gx) * scale, y0 = y + gy * scale;
                for (int py = y0; py < y0 + scale; py++)
                    for (int px = x0; px < x0 + scale; px++)
                        if (px >= 0 && px < width && py >= 0 && py < height)
                            memcpy(rgb + 3 * ((size_t)py * (size_t)width + (size_t)px),
                                   colour, 3);
            }
}
