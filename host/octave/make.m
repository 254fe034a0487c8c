function mexfile = make(varargin)
% MAKE  Build beamslider_mex, the MEX gateway of beamslider_run and
% beamslider_sim, under GNU Octave (mkoctfile --mex) or MATLAB (mex).
%
%   make                      build into <repository>/build/octave/PRECISION
%   make('outdir', DIR)       build into DIR
%   make('precision', P)      'double' (default) or 'float': which library
%   make('library', WHERE)    'auto' (default): the repository's build/lib if
%                             it is there, else pkg-config; 'build' or
%                             'pkg-config' to insist on one
%   make('builddir', DIR)     the repository's build folder (make BUILD=DIR;
%                             default <repository>/build)
%
% The library (libbeamslider-host) comes from the repository, built there by
% `make lib` (or `make REAL=double lib-one`), and is linked in as its
% archives, so the MEX file needs no beamslider library at run time (only
% libinih and libcjson); or from an installed tree found by pkg-config
% (`make install`; set PKG_CONFIG_PATH for a PREFIX such as $HOME/.local),
% linked as the shared library with its folder as run path.
% Then:  addpath(<repository>/host/octave, DIR)   (docs/octave.md)
%
% Returns the path of the MEX file. Writes only into DIR.

  opts = struct('outdir', '', 'precision', 'double', 'library', 'auto', 'builddir', '');
  if mod(numel(varargin), 2) ~= 0
    error('beamslider:usage', 'make: options come in name/value pairs');
  end
  for k = 1:2:numel(varargin)
    name = varargin{k};
    if ~ischar(name) || ~isfield(opts, name)
      error('beamslider:usage', 'make: unknown option; allowed: outdir, precision, library, builddir');
    end
    opts.(name) = varargin{k + 1};
  end
  if ~any(strcmp(opts.precision, {'double', 'float'}))
    error('beamslider:usage', 'make: precision ''%s''; allowed: ''double'', ''float''', opts.precision);
  end
  if ~any(strcmp(opts.library, {'auto', 'build', 'pkg-config'}))
    error('beamslider:usage', 'make: library ''%s''; allowed: ''auto'', ''build'', ''pkg-config''', opts.library);
  end

  here = fileparts(mfilename('fullpath'));
  root = fileparts(fileparts(here));
  if isempty(opts.builddir)
    opts.builddir = fullfile(root, 'build');
  end
  if isempty(opts.outdir)
    opts.outdir = fullfile(opts.builddir, 'octave', opts.precision);
  end
  if ~is_absolute(opts.outdir)
    opts.outdir = fullfile(pwd(), opts.outdir);
  end
  if ~exist(opts.outdir, 'dir')
    mkdir(opts.outdir);
  end
  listing = dir(fullfile(here, 'src', '*.c'));
  sources = fullfile(here, 'src', {listing.name});
  [flags, libs] = find_library(root, opts);
  % the repository's warnings (Makefile WARNINGS); errors only where the
  % headers are known to pass them (Octave's mex.h; MATLAB's are not tested here)
  cflags = ['-std=c99 -O2 -ffp-contract=off -Wall -Wextra -Wdouble-promotion -Wfloat-conversion -Wundef ', ...
            '-Wshadow -Wstrict-prototypes -Wvla'];
  mexfile = fullfile(opts.outdir, ['beamslider_mex.' mexext()]);

  if exist('OCTAVE_VERSION', 'builtin')
    % mkoctfile takes the compiler's flags from the environment, and leaves
    % its objects in the working folder: compile there in the output folder.
    old_cflags = getenv('CFLAGS');
    old_dir = pwd();
    cleanup = onCleanup(@() restore(old_cflags, old_dir));
    setenv('CFLAGS', [mkoctfile('-p', 'CFLAGS') ' ' cflags ' -Werror']);
    cd(opts.outdir);
    [out, status] = mkoctfile('--mex', '-o', mexfile, flags{:}, sources{:}, libs{:});
    if status ~= 0
      error('beamslider:build', 'make: mkoctfile failed:\n%s', out);
    end
  else
    % mex takes linker options (pkg-config's -Wl,-rpath) only through LDFLAGS
    linker = strncmp(libs, '-Wl,', 4) | strcmp(libs, '-pthread');
    mex('-outdir', opts.outdir, '-output', 'beamslider_mex', ['CFLAGS=$CFLAGS ' cflags], ...
        ['LDFLAGS=$LDFLAGS ' sprintf('%s ', libs{linker})], flags{:}, sources{:}, libs{~linker});
  end
end

function yes = is_absolute(path)
  yes = ~isempty(path) && (path(1) == '/' || path(1) == '\\' || (numel(path) > 1 && path(2) == ':'));
end

function restore(cflags, folder)
  setenv('CFLAGS', cflags);
  cd(folder);
end

% The compiler's include flags and the linker's arguments for the library.
function [flags, libs] = find_library(root, opts)
  p = opts.precision;
  lib = fullfile(opts.builddir, 'lib');
  archives = {fullfile(lib, ['libbeamslider-host-' p '.a']), fullfile(lib, ['libbeamslider-' p '.a'])};
  config = fullfile(opts.builddir, p, 'include');
  in_build = exist(archives{1}, 'file') && exist(archives{2}, 'file') ...
             && exist(fullfile(config, 'bs_build_config.h'), 'file');
  if strcmp(opts.library, 'build') || (strcmp(opts.library, 'auto') && in_build)
    if ~in_build
      error('beamslider:build', ['make: no %s library in %s (build it there: make REAL=%s lib-one)'], ...
            p, lib, p);
    end
    flags = {['-I' config], ['-I' fullfile(root, 'core', 'include')], ['-I' fullfile(root, 'host', 'include')]};
    libs = [archives, {'-linih', '-lcjson', '-lm', '-lpthread'}];
    return;
  end
  package = ['beamslider-host-' p];
  [status, cflags] = system(['pkg-config --cflags ' package]);
  [status2, ldflags] = system(['pkg-config --libs ' package]);
  if status ~= 0 || status2 ~= 0
    error('beamslider:build', ['make: no %s library: neither in %s nor found by pkg-config %s ', ...
          '(make install, and PKG_CONFIG_PATH=PREFIX/lib/pkgconfig)'], p, lib, package);
  end
  flags = strsplit(strtrim(cflags));
  libs = strsplit(strtrim(ldflags));
end
