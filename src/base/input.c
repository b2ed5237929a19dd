/*
 * base/input.c -- files photon reads: regular files only, read to their size (input.h).
 *
 * C99 cannot ask what kind of file a name is, so input_open() asks by behaviour:
 * "NAME/." opens only for a directory, and a FIFO is found by an open that does not wait
 * for its writer (file_kind.h); a pipe cannot seek to its end; and a regular file has
 * nothing past its end, where a device such as /dev/zero (which says its size is 0) goes
 * on giving bytes. A file that passes them all is read to the size it had.
 */
#include "input.h"

#include <errno.h>
#include <string.h>

#include "file_kind.h"
#include "output.h"

/* Measures in->f's size and makes sure nothing follows it; leaves it at its start. */
static int measure(struct input *in, struct error *err)
{
    if (fseek(in->f, 0, SEEK_END) != 0 || (in->size = ftell(in->f)) < 0)
        return error_set(err, in->name, 0, "not a regular file (it cannot tell its size: "
                         "a pipe or a terminal?)");
    errno = 0;
    int c = getc(in->f);
    if (ferror(in->f))
        return error_set(err, in->name, 0, "cannot be read: %s", input_failure());
    if (c != EOF)
        return error_set(err, in->name, 0, "not a regular file (it gives bytes past its "
                         "size of %ld: a device such as /dev/zero?)", in->size);
    if (fseek(in->f, 0, SEEK_SET) != 0)
        return error_set(err, in->name, 0, "not a regular file (it cannot go back to its "
                         "start)");
    return 0;
}

const char *input_failure(void)
{
    return errno != 0 ? strerror(errno) : "unknown reason";
}

int input_open(struct input *in, const char *name, struct error *err)
{
    in->name = name;
    in->size = 0;
    in->offset = 0;
    in->line = 0;
    in->f = NULL;
    if (name[0] == '\0')
        return error_set(err, "", 0, "an empty file name");
    if (file_is_directory(name))
        return error_set(err, name, 0, "is a directory");
    int pipe;
    errno = 0;
    in->f = file_open_read(name, &pipe);
    if (pipe)
        return error_set(err, name, 0, "is a FIFO or a terminal, not a regular file (photon "
                         "reads files it can measure)");
    if (in->f == NULL)
        return error_set(err, name, 0, "cannot open: %s", input_failure());
    if (measure(in, err) < 0 || output_refuse_input(name, in->size, err) < 0) {
        input_close(in);
        return -1;
    }
    return 0;
}

int input_line(struct input *in, char *text, size_t size, struct error *err)
{
    size_t n = 0;
    int c = EOF;
    errno = 0;
    while (n + 1 < size && (c = getc(in->f)) != EOF) {
        if (c == '\0')
            return error_set(err, in->name, in->line + 1, "a NUL byte in the line (is it a "
                             "binary file?)");
        text[n++] = (char)c;
        if (c == '\n')
            break;
    }
    text[n] = '\0';
    if (ferror(in->f))
        return error_set(err, in->name, 0, "cannot be read: %s", input_failure());
    if (n == 0)
        return 0;
    in->line++;
    in->offset += (long)n;
    if (in->offset > in->size)
        return error_set(err, in->name, in->line, "the file goes on past the %ld bytes it "
                         "had when opened (not a regular file?)", in->size);
    if (c != '\n' && n + 1 == size) { /* text is full: the line may end right here */
        int next = getc(in->f);
        if (next != '\n' && next != EOF)
            return error_set(err, in->name, in->line, "line longer than %zu bytes, its "
                             "newline included", size);
        in->offset += next == '\n'; /* its newline, read but not kept: the text is full */
        if (in->offset > in->size)
            return error_set(err, in->name, in->line, "the file goes on past the %ld bytes "
                             "it had when opened (not a regular file?)", in->size);
    }
    return 1;
}

void input_close(struct input *in)
{
    if (in->f != NULL)
        fclose(in->f);
    in->f = NULL;
}
