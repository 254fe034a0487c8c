/* map_store.h - a map's folder: its identity and its result files
 * (docs/maps.md section 4).
 *
 * DIR/map-identity.txt says which map the folder holds: the code (version,
 * precision), the scene (scene_values_hash of the scene after --set,
 * without the varied fields), the grid (each varied field and its values),
 * the repeats and their perturbation. It is written once, by
 * whichever command comes first (written aside, then linked into place:
 * link() fails if the name exists, also on NFS, so two shards starting
 * together cannot both write it); a command whose identity differs is
 * refused before it writes anything, with what differs. Lines starting
 * "info " (the source revision, the scene's name and file, the --set
 * options, the command) are not compared: a map may be resumed by a build
 * of another source revision of the same version (any commit changes the
 * revision, and a map can take hours), with a warning.
 *
 * Results: every process that runs cases appends to its own file,
 * DIR/runs-HOST-PID.csv (created with O_EXCL; -2, -3, ... if the name is
 * taken), so that no two processes, on one machine or over NFS, ever append
 * to one file. A row is appended with one write() of the whole line and then
 * fdatasync()ed: a kill loses at most the cases in flight, a crash of the
 * machine at most the rows not yet synced. A row that did not fully reach
 * the file (a full disk) is cut off again by its writer. Readers take a
 * line only if it is whole (map_row_valid: newline, columns, check), so a
 * line torn by a kill -9 or a power cut is ignored, never merged.
 */
#ifndef MAP_STORE_H
#define MAP_STORE_H

#include <stddef.h>
#include <sys/types.h>
#include "map_grid.h"

#define MAP_IDENTITY_FILE "map-identity.txt"

/* The identity text of a map of grid on base (scene_path: the scene file,
 * command: the command line, both informational). Returns a malloc'd text,
 * NULL when out of memory. */
char *map_identity_text(const map_grid *grid, const scene_file *base, const char *scene_path,
                        const char *command);

/* Makes dir hold the map of identity: creates dir (and the folders above it
 * that are missing; a refusal names the one that could not be made) and
 * writes the identity if it has none, else compares. Refused, with what
 * differs: a dir of another map, a dir holding other files but no identity,
 * a path that is not a folder. 0; 1 when dir's map was started by another
 * source revision (err says so: a warning); -1 with err (nothing written). */
int map_dir_claim(const char *dir, const char *identity, char *err, size_t size);

/* Reads dir's identity back into a grid (for map-merge and map-plot) and
 * its info scene name into scene (size SCENE_TEXT). 0, or -1 with err. */
int map_identity_read(const char *dir, map_grid *grid, char *scene, char *err, size_t size);

/* The rows found in dir's result files: row[c] is case c's row (malloc'd,
 * the first whole one found, in file-name order), NULL if none. */
typedef struct map_found {
    char **row;
    long done;         /* cases with a row */
    long torn;         /* last lines without their newline (a kill mid-write) */
    long invalid;      /* other lines that are not whole rows of this grid */
    long duplicates;   /* rows of a case found again */
    long differing;    /* of those, rows whose result columns differ from the first */
} map_found;

/* Reads every DIR/runs-*.csv. 0, or -1 with err (found is then empty). */
int map_found_read(const char *dir, const map_grid *grid, map_found *found, char *err, size_t size);
void map_found_free(map_found *found, long cases);

/* A result file of this process in dir: created (O_EXCL), with the header
 * line. Returns the descriptor, -1 with err. */
int map_results_create(const char *dir, const map_grid *grid, char *path, size_t path_size, char *err,
                       size_t size);

/* Appends row (a whole line) to fd with one write() and syncs it; *length
 * is the file's size before, updated. On a short write the part written is
 * cut off again. 0, or -1 with err. */
int map_results_append(int fd, const char *row, off_t *length, char *err, size_t size);

#endif
