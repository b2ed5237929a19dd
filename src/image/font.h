/*
 * image/font.h -- a tiny bitmap font for the numbers written into pictures: the labels
 * of a false-colour picture's scale (false_colour.h). Glyphs and drawing in font.c.
 */
#ifndef PHOTON_FONT_H
#define PHOTON_FONT_H

#define FONT_WIDTH 5   /* a glyph's columns                                  */
#define FONT_HEIGHT 7  /* and rows, digits and capitals full height          */
#define FONT_ADVANCE 6 /* from one glyph's left column to the next one's     */

/* The characters that have a glyph: the digits, ". e - + %", "p" and the space. */
#define FONT_CHARACTERS "0123456789.e-+%p "

/* Whether c has a glyph. */
int font_has(char c);

/* Whether glyph c is inked at column x (0 .. FONT_WIDTH - 1) and row y (0 .. FONT_HEIGHT
 * - 1, from the top); a character without a glyph is a full box, so that it shows. */
int font_pixel(char c, int x, int y);

/* The width in pixels of text drawn at scale (each glyph pixel a scale x scale square):
 * FONT_ADVANCE per character less the space after the last; 0 for "". */
int font_text_width(const char *text, int scale);

/* Draws text with its top-left corner at (x, y) into rgb, width x height pixels of R G B
 * bytes, rows from the top: every inked pixel becomes colour, the rest is left as it is;
 * what falls outside the picture is not drawn. */
void font_draw(unsigned char *rgb, int width, int height, int x, int y, int scale,
               const char *text, const unsigned char colour[3]);

#endif
