/*
 * C test of the cycleref C interface, built and run by ffi/tests/c_program.rs:
 *
 *     expand_example PATH/TO/examples/gsk988-m68x6.nc
 *
 * Expands the M68x6 example of the GSK 988TA manual (O0013) and checks the
 * moves against the golden test (spec/tests/golden.rs, gsk988_m68x6): four
 * rough and two finishing passes of five moves each. Then reads the same
 * program through the streaming cursor, steps the same cycle through the
 * G76 handle API, and checks the error paths.
 *
 * Prints one line per failed check and exits with the number of failures
 * (capped at 100), 0 when every check passes.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cycleref.h"

static int failures = 0;

#define CHECK(cond)                                                                     \
    do {                                                                                \
        if (!(cond)) {                                                                  \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);   \
            failures++;                                                                 \
        }                                                                               \
    } while (0)

#define CHECK_EQ(a, b)                                                                  \
    do {                                                                                \
        long long a_ = (long long)(a), b_ = (long long)(b);                             \
        if (a_ != b_) {                                                                 \
            fprintf(stderr, "%s:%d: check failed: %s == %s (%lld != %lld)\n", __FILE__, \
                    __LINE__, #a, #b, a_, b_);                                          \
            failures++;                                                                 \
        }                                                                               \
    } while (0)

static char *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        perror(path);
        return NULL;
    }
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    size_t r;
    while (buf && (r = fread(buf + n, 1, cap - n, f)) > 0) {
        n += r;
        if (n == cap) {
            char *bigger = realloc(buf, cap * 2);
            if (!bigger) free(buf);
            buf = bigger;
            cap *= 2;
        }
    }
    fclose(f);
    *len = n;
    return buf;
}

/* Every field but `line` (0 for moves of the step API). */
static int same_move(const CyclerefMove *a, const CyclerefMove *b) {
    return a->x == b->x && a->z == b->z && a->decimals == b->decimals && a->cycle == b->cycle &&
           a->motion == b->motion && a->role == b->role && a->lead_word == b->lead_word &&
           a->lead_mantissa == b->lead_mantissa && a->lead_scale == b->lead_scale &&
           a->start_angle_num == b->start_angle_num &&
           a->start_angle_den == b->start_angle_den && a->sync == b->sync &&
           a->has_pass == b->has_pass && a->pass_kind == b->pass_kind &&
           a->pass_number == b->pass_number && a->pass_start == b->pass_start &&
           a->pass_depth == b->pass_depth && a->pass_cut == b->pass_cut &&
           a->pass_flank == b->pass_flank;
}

/* The golden moves of the M68x6 example. */
static void check_m68x6(const CyclerefMove *m, size_t n) {
    CHECK_EQ(n, 30);
    if (n < 30) return;

    /* Pass 1, rough: approach to B1 = X64.400 Z8.961. */
    CHECK_EQ(m[0].motion, CYCLEREF_MOTION_RAPID);
    CHECK_EQ(m[0].role, CYCLEREF_ROLE_APPROACH);
    CHECK_EQ(m[0].x, 64400);
    CHECK_EQ(m[0].z, 8961);
    CHECK_EQ(m[0].decimals, 3);
    CHECK_EQ(m[0].cycle, CYCLEREF_CYCLE_G76);
    CHECK_EQ(m[0].has_pass, 1);
    CHECK_EQ(m[0].pass_kind, CYCLEREF_PASS_KIND_ROUGH);
    CHECK_EQ(m[0].pass_number, 1);
    CHECK_EQ(m[0].pass_start, 1);
    CHECK_EQ(m[0].pass_depth, 1800);
    CHECK_EQ(m[0].pass_cut, 1800);
    CHECK_EQ(m[0].pass_flank, CYCLEREF_FLANK_RIGHT);
    CHECK_EQ(m[0].sync, 0);

    /* The cut to the run-out start X64.400 Z-59.000, F6, synchronised. */
    CHECK_EQ(m[1].motion, CYCLEREF_MOTION_THREAD);
    CHECK_EQ(m[1].role, CYCLEREF_ROLE_CUT);
    CHECK_EQ(m[1].x, 64400);
    CHECK_EQ(m[1].z, -59000);
    CHECK_EQ(m[1].lead_word, CYCLEREF_LEAD_WORD_F);
    CHECK_EQ(m[1].lead_mantissa, 6);
    CHECK_EQ(m[1].lead_scale, 0);
    CHECK_EQ(m[1].start_angle_num, 0);
    CHECK_EQ(m[1].start_angle_den, 1);
    CHECK_EQ(m[1].sync, 1);

    /* The run-out: 45 degrees, K = 0.5 x 6 = 3, to X70.400 Z-62.000. */
    CHECK_EQ(m[2].motion, CYCLEREF_MOTION_THREAD);
    CHECK_EQ(m[2].role, CYCLEREF_ROLE_RUN_OUT);
    CHECK_EQ(m[2].x, 70400);
    CHECK_EQ(m[2].z, -62000);
    CHECK_EQ(m[2].lead_mantissa, 6);
    CHECK_EQ(m[2].sync, 0);

    /* Retract to X80, return to A = X80.000 Z10.000. */
    CHECK_EQ(m[3].motion, CYCLEREF_MOTION_RAPID);
    CHECK_EQ(m[3].role, CYCLEREF_ROLE_RETRACT);
    CHECK_EQ(m[3].x, 80000);
    CHECK_EQ(m[3].z, -62000);
    CHECK_EQ(m[4].motion, CYCLEREF_MOTION_RAPID);
    CHECK_EQ(m[4].role, CYCLEREF_ROLE_RETURN);
    CHECK_EQ(m[4].x, 80000);
    CHECK_EQ(m[4].z, 10000);

    /* Every pass: its start point, depth and cut (golden test). */
    static const struct {
        long long x, z, depth, cut;
        CyclerefPassKind kind;
        unsigned number;
    } passes[6] = {
        {64400, 8961, 1800, 1800, CYCLEREF_PASS_KIND_ROUGH, 1},
        {62908, 8530, 2546, 746, CYCLEREF_PASS_KIND_ROUGH, 2},
        {61764, 8200, 3118, 572, CYCLEREF_PASS_KIND_ROUGH, 3},
        {60840, 7933, 3580, 462, CYCLEREF_PASS_KIND_ROUGH, 4},
        {60640, 7933, 3680, 100, CYCLEREF_PASS_KIND_FINISH, 1},
        {60640, 7933, 3680, 0, CYCLEREF_PASS_KIND_FINISH, 2},
    };
    for (int p = 0; p < 6; p++) {
        const CyclerefMove *a = &m[5 * p];
        CHECK_EQ(a->role, CYCLEREF_ROLE_APPROACH);
        CHECK_EQ(a->x, passes[p].x);
        CHECK_EQ(a->z, passes[p].z);
        CHECK_EQ(a->pass_depth, passes[p].depth);
        CHECK_EQ(a->pass_cut, passes[p].cut);
        CHECK_EQ(a->pass_kind, passes[p].kind);
        CHECK_EQ(a->pass_number, passes[p].number);
        CHECK_EQ(a[1].z, -59000);
        CHECK_EQ(a[2].x, passes[p].x + 6000);
        CHECK_EQ(a[2].z, -62000);
        CHECK_EQ(a[4].x, 80000);
        CHECK_EQ(a[4].z, 10000);
        for (int i = 0; i < 5; i++) {
            CHECK_EQ(a[i].sync, i == 1);
            CHECK_EQ(a[i].has_pass, 1);
            CHECK_EQ(a[i].pass_number, passes[p].number);
        }
    }
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s examples/gsk988-m68x6.nc\n", argv[0]);
        return 100;
    }
    size_t len = 0;
    char *program = read_file(argv[1], &len);
    if (!program) return 100;

    printf("cycleref %s\n", cycleref_version());
    CyclerefOptions opts = cycleref_options_default();
    CHECK_EQ(opts.profile, CYCLEREF_PROFILE_GSK988);
    opts.profile = CYCLEREF_PROFILE_GSK988;
    CyclerefError err;
    size_t count = 12345;

    /* Sizing: capacity 0 with a NULL buffer gives the count. */
    CyclerefStatus s = cycleref_expand(program, len, &opts, NULL, 0, &count, &err);
    CHECK_EQ(s, CYCLEREF_STATUS_BUFFER_TOO_SMALL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_BUFFER_TOO_SMALL);
    CHECK_EQ(count, 30);

    /* Too small a buffer: the first `capacity` moves, and the count. */
    CyclerefMove small[7];
    memset(small, 0xAB, sizeof small);
    count = 0;
    s = cycleref_expand(program, len, &opts, small, 7, &count, &err);
    CHECK_EQ(s, CYCLEREF_STATUS_BUFFER_TOO_SMALL);
    CHECK_EQ(count, 30);

    /* The whole program. */
    CyclerefMove *moves = calloc(count, sizeof *moves);
    size_t needed = count;
    s = cycleref_expand(program, len, &opts, moves, needed, &count, &err);
    if (s != CYCLEREF_STATUS_OK)
        fprintf(stderr, "cycleref_expand: %s: line %zu: %s\n", cycleref_status_name(s), err.line,
                err.message);
    CHECK_EQ(s, CYCLEREF_STATUS_OK);
    CHECK_EQ(err.status, CYCLEREF_STATUS_OK);
    CHECK_EQ(err.message[0], '\0');
    check_m68x6(moves, count);
    for (size_t i = 0; i < count; i++) CHECK_EQ(moves[i].line, 6); /* G76 block 2 */
    for (size_t i = 0; i < 7 && count == 30; i++) {
        CHECK(same_move(&small[i], &moves[i]));
        CHECK_EQ(small[i].line, moves[i].line);
    }

    /* The streaming cursor: the same moves, one at a time. It keeps its own
       copy of the text, so the caller's may go right after the open. */
    char *copy = malloc(len ? len : 1);
    if (copy) memcpy(copy, program, len);
    CyclerefCursor *cur = copy ? cycleref_cursor_open(copy, len, &opts, &err) : NULL;
    free(copy);
    CHECK(cur != NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_OK);
    if (cur) {
        CyclerefMove streamed[40];
        size_t n = 0;
        int r = -100;
        while (n < 40 && (r = cycleref_cursor_next(cur, &streamed[n], &err)) == 1) n++;
        CHECK_EQ(r, 0);
        CHECK_EQ(err.status, CYCLEREF_STATUS_OK);
        CHECK_EQ(cycleref_cursor_next(cur, &streamed[39], NULL), 0); /* stays at the end */
        CHECK_EQ(n, 30);
        check_m68x6(streamed, n);
        for (size_t i = 0; i < n && i < count; i++) {
            CHECK(same_move(&streamed[i], &moves[i]));
            CHECK_EQ(streamed[i].line, 6); /* the cycle's G76 block 2 */
        }
        CHECK_EQ(cycleref_cursor_next(cur, NULL, &err), CYCLEREF_STATUS_INVALID_ARGUMENT);
        CHECK(strstr(err.message, "out") != NULL);
        cycleref_cursor_close(cur);
    }
    /* Closing before the end is fine, and so is NULL. */
    cur = cycleref_cursor_open(program, len, &opts, NULL);
    CHECK(cur != NULL);
    CyclerefMove first;
    CHECK_EQ(cycleref_cursor_next(cur, &first, NULL), 1);
    CHECK_EQ(first.x, 64400);
    CHECK_EQ(first.z, 8961);
    cycleref_cursor_close(cur);
    cycleref_cursor_close(NULL);
    CHECK_EQ(cycleref_cursor_next(NULL, &first, &err), CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK(cycleref_cursor_open(NULL, 0, &opts, &err) == NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK(cycleref_cursor_open(program, len, NULL, NULL) == NULL);

    /* The step API on the same cycle, its parameters worked out by hand:
       A = (80, 10), D = (60.64, -62), k 3.68, delta-d 1.8, delta-d min
       0.15, d 0.1, P020560: m 2, r 05 (chamfer 0.5 lead), a 60; the
       988TA's chamfer angle parameter 5131 = 0 is 45 degrees. */
    CyclerefG76Params p;
    memset(&p, 0, sizeof p);
    p.increment = CYCLEREF_INCREMENT_IS_B;
    p.start_x = 80000;
    p.start_z = 10000;
    p.end_x = 60640;
    p.end_z = -62000;
    p.taper = 0;
    p.thread_height = 3680;
    p.first_depth = 1800;
    p.min_cut = 150;
    p.finishing_allowance = 100;
    p.finishing_passes = 2;
    p.tool_angle = 60;
    p.infeed = CYCLEREF_INFEED_RIGHT_FLANK;
    p.lead_in = 0;
    p.starts = 1;
    p.lead_word = CYCLEREF_LEAD_WORD_F;
    p.lead_mantissa = 6;
    p.lead_scale = 0;
    p.run_out_kind = CYCLEREF_RUN_OUT_KIND_CHAMFER;
    p.run_out_tenths = 5;
    p.run_out_angle = 45;
    p.pass_limit = 0;

    CyclerefG76 *h = cycleref_g76_new(&p, &err);
    CHECK(h != NULL);
    if (h) {
        CyclerefMove stepped[40];
        size_t n = 0;
        int r = -100;
        while (n < 40 && (r = cycleref_g76_next(h, &stepped[n])) == 1) n++;
        CHECK_EQ(r, 0);
        CHECK_EQ(cycleref_g76_next(h, &stepped[39]), 0); /* stays at the end */
        CHECK_EQ(n, 30);
        check_m68x6(stepped, n);
        for (size_t i = 0; i < n && i < count; i++) {
            CHECK(same_move(&stepped[i], &moves[i]));
            CHECK_EQ(stepped[i].line, 0);
        }
        CHECK_EQ(cycleref_g76_next(NULL, &stepped[0]), CYCLEREF_STATUS_INVALID_ARGUMENT);
        CHECK_EQ(cycleref_g76_next(h, NULL), CYCLEREF_STATUS_INVALID_ARGUMENT);
        cycleref_g76_free(h);
    }
    cycleref_g76_free(NULL);

    /* The manual's alarm from the step API: A inside the thread. */
    CyclerefG76Params inside = p;
    inside.start_x = 62000;
    h = cycleref_g76_new(&inside, &err);
    CHECK(h == NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_CYCLE_ERROR);
    CHECK(strstr(err.message, "start point A") != NULL);
    cycleref_g76_free(h);

    /* An enum value out of range is refused, not trusted. */
    CyclerefG76Params bad = p;
    bad.infeed = 7;
    CHECK(cycleref_g76_new(&bad, &err) == NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "infeed") != NULL);
    CHECK(cycleref_g76_new(NULL, NULL) == NULL);

    /* A program error: G76 block 2 (line 4) without P(k). */
    static const char missing_p[] =
        "G50 X100 Z50 M3 S300;\n"
        "G00 X80 Z10;\n"
        "G76 P020560 Q0.150 R0.1;\n"
        "G76 X60.64 Z-62 Q1.800 F6;\n";
    count = 99;
    s = cycleref_expand(missing_p, strlen(missing_p), &opts, moves, needed, &count, &err);
    CHECK_EQ(s, CYCLEREF_STATUS_PROGRAM_ERROR);
    CHECK_EQ(err.status, CYCLEREF_STATUS_PROGRAM_ERROR);
    CHECK_EQ(err.line, 4);
    CHECK(strstr(err.message, "P(k)") != NULL);
    CHECK_EQ(count, 0);
    printf("expected error: %s\n", err.message);

    /* The cursor refuses the same program at the open: nothing is
       delivered from a program with an error, even in its last cycle. */
    CHECK(cycleref_cursor_open(missing_p, strlen(missing_p), &opts, &err) == NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_PROGRAM_ERROR);
    CHECK_EQ(err.line, 4);
    CHECK(strstr(err.message, "P(k)") != NULL);
    /* A cycle's alarm: the second cycle starts at X62, inside the thread. */
    static const char alarm[] =
        "G50 X100 Z50 M3 S300;\n"
        "G00 X80 Z10;\n"
        "G76 P020560 Q0.150 R0.1;\n"
        "G76 X60.64 Z-62 P3.680 Q1.800 F6;\n"
        "G00 X62;\n"
        "G76 X60.64 Z-62 P3.680 Q1.800 F6;\n";
    CHECK(cycleref_cursor_open(alarm, strlen(alarm), &opts, &err) == NULL);
    CHECK_EQ(err.status, CYCLEREF_STATUS_CYCLE_ERROR);
    CHECK_EQ(err.line, 6);
    CHECK(strstr(err.message, "start point A") != NULL);
    printf("expected error: %s\n", err.message);

    /* Invalid arguments. */
    s = cycleref_expand(NULL, 0, &opts, moves, needed, &count, &err);
    CHECK_EQ(s, CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK_EQ(cycleref_expand(program, len, NULL, moves, needed, &count, NULL),
             CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK_EQ(cycleref_expand(program, len, &opts, moves, needed, NULL, NULL),
             CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK_EQ(cycleref_expand(program, len, &opts, NULL, 5, &count, NULL),
             CYCLEREF_STATUS_INVALID_ARGUMENT);
    CyclerefOptions bad_opts = opts;
    bad_opts.profile = 4;
    CHECK_EQ(cycleref_expand(program, len, &bad_opts, moves, needed, &count, &err),
             CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "profile") != NULL);

    /* A parameter file: IS-C through the TOML text (the program's values
       are then 0.0001 mm increments: 64.4000 is 644000). */
    static const char toml[] = "increment = \"is-c\"\n";
    CyclerefOptions is_c = opts;
    is_c.params_toml = toml;
    is_c.params_toml_len = strlen(toml);
    s = cycleref_expand(program, len, &is_c, moves, needed, &count, &err);
    CHECK_EQ(s, CYCLEREF_STATUS_OK);
    CHECK_EQ(count, 30);
    CHECK_EQ(moves[0].decimals, 4);
    CHECK_EQ(moves[0].x, 644000);
    is_c.params_toml = "increment = 3";
    is_c.params_toml_len = strlen(is_c.params_toml);
    CHECK_EQ(cycleref_expand(program, len, &is_c, moves, needed, &count, &err),
             CYCLEREF_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "parameter file") != NULL);

    free(moves);
    free(program);
    if (failures == 0) printf("all checks passed\n");
    return failures > 100 ? 100 : failures;
}
