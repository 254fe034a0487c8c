function check_octave(precision, long_hash, short_hash, short_t_end, tmp)
% CHECK_OCTAVE  The Octave bridge (host/octave) against the CLI, run by
% tests/check_octave.sh (which passes the CLI's hashes, computed at test time):
%   long_hash    `beamslider run configs/fig6.ini` (60 s), or '' to skip
%   short_hash   `beamslider run configs/fig6.ini --t-end SHORT_T_END
%                 --set excitation.frequency=120`
% tmp: a scratch folder. Prints "ok   - ..." / "FAIL - ..." lines; fails
% (error) when any check does.
  failed = 0;
  scene = fullfile(pwd(), 'configs', 'fig6.ini');

  v = beamslider_mex('version');
  failed = failed + check(strcmp(v.precision, precision), ...
                          sprintf('the gateway is the %s build (is %s)', precision, v.precision));

  % (a) beamslider_run reaches the CLI's state hash, with the issue's call form
  if ~isempty(long_hash)
    r = beamslider_run('configs/fig6.ini');
    failed = failed + check(strcmp(r.summary.hash, long_hash), ...
      sprintf('fig6 60 s: beamslider_run hash %s, CLI %s', r.summary.hash, long_hash));
    failed = failed + check(numel(r.t) == 60001 && abs(r.t(end) - 60) < 1e-9 && numel(r.s) == 60001 ...
                            && r.s(end) == r.summary.s_final, ...
      'fig6 60 s: a row every millisecond from 0 to 60 s, the last s is s_final');
    failed = failed + check(numel(r.periods.t) > 7000 && all(diff(r.periods.t) > 0), ...
      'fig6 60 s: one row per excitation period');
  end
  r = beamslider_run('configs/fig6.ini', 't_end', short_t_end, 'set', {'excitation.frequency', 120});
  failed = failed + check(strcmp(r.summary.hash, short_hash), ...
    sprintf('fig6 %g s at 120 Hz: beamslider_run hash %s, CLI %s', short_t_end, r.summary.hash, short_hash));
  failed = failed + check(isequal(r.summary.set, {'run.t_end', short_t_end; 'excitation.frequency', 120}), ...
    'the summary lists the overrides, numbers as numbers');

  % (b) errors name the file, line, field and range
  failed = failed + check_error(@() beamslider_run(scene, 'set', {'excitation.frequency', -1}), ...
    'beamslider:input', {'[excitation] frequency = -1', 'allowed'}, 'an override out of range');
  failed = failed + check_error(@() beamslider_run(scene, 'set', {'excitation.frequenc', 1}), ...
    'beamslider:input', {'unknown field [excitation] frequenc'}, 'an unknown field');
  bad = fullfile(tmp, 'bad.ini');
  fid = fopen(bad, 'w');
  fprintf(fid, '[scene]\nbase = %s\n[numerics]\ndt = 0\n', scene);
  fclose(fid);
  failed = failed + check_error(@() beamslider_run(bad), 'beamslider:input', ...
    {'bad.ini:4: [numerics] dt = 0', 'allowed'}, 'a scene file''s bad line');
  failed = failed + check_error(@() beamslider_sim('init', bad), 'beamslider:input', ...
    {'bad.ini:4: [numerics] dt = 0'}, 'the same from beamslider_sim init');
  failed = failed + check_error(@() beamslider_run(scene, 'tend', 1), 'beamslider:usage', ...
    {'unknown option ''tend''', '''t_end'''}, 'an unknown option');

  failed = failed + check_error(@() beamslider_run(scene, 't_end', 0.1, 'set', {'excitation.acceleration', 1e15}), ...
    'beamslider:failed', {'fig6: stopped at t = ', 'stability limit'}, 'a run that stops');
  failed = failed + check_error(@() beamslider_sim('step_measured', beamslider_sim('init', scene), 1e15 * ones(1, 9)), ...
    'beamslider:failed', {'fig6: step 2 of this call', 'stability limit'}, 'a step call that stops');

  % (c) the stepping state: whole against halves through a .mat file and
  % unloading the gateway, and against the CLI
  n = round(short_t_end / 2e-5);
  st = beamslider_sim('init', 'configs/fig6.ini', 'set', {'excitation.frequency', 120});
  whole = beamslider_sim('step', st, n);
  [half, out] = beamslider_sim('step', st, n / 2, 100);
  save(fullfile(tmp, 'half.mat'), 'half', '-mat');
  clear half beamslider_mex   % unloads it (timed: the next call loads the scene again)
  saved = load(fullfile(tmp, 'half.mat'));
  rest = beamslider_sim('step', saved.half, n / 2);
  iw = beamslider_sim('info', whole);
  ir = beamslider_sim('info', rest);
  failed = failed + check(strcmp(iw.hash, short_hash) && iw.steps == n, ...
    sprintf('%d steps in one call: hash %s, CLI %s', n, iw.hash, short_hash));
  failed = failed + check(isequal(whole, rest) && strcmp(ir.hash, iw.hash), ...
    'two halves, the state saved to a .mat file and the gateway unloaded between: the same state as one call');
  failed = failed + check(numel(out.t) == n / 200 && abs(out.t(end) - short_t_end / 2) < 1e-12, ...
    'the series of a step call: a row every `every` steps after the first');
  a = 14 * cos(2 * pi * 120 * ((1:2000)' - 0.5) * 2e-5);
  m1 = beamslider_sim('step_measured', st, a);
  m2 = beamslider_sim('step_measured', beamslider_sim('step_measured', st, a(1:700)), a(701:end));
  failed = failed + check(isequal(m1, m2) && ~isequal(m1, beamslider_sim('step', st, 2000)), ...
    'measured steps: halves give the state of one call (and not the harmonic one)');

  % (d) a state that is not one, or of another scene, is refused
  failed = failed + check_error(@() beamslider_sim('step', uint8(1:40)', 1), 'beamslider:state', ...
    {'not a beamslider_sim state'}, 'a uint8 array that is no state');
  damaged = st;
  damaged(1000) = bitxor(damaged(1000), uint8(1));
  failed = failed + check_error(@() beamslider_sim('step', damaged, 1), 'beamslider:state', ...
    {'refused'}, 'a state whose checkpoint was changed');
  other = st;
  at = strfind(char(other'), 'frequency=120');
  other(at + 12) = uint8('1');
  failed = failed + check_error(@() beamslider_sim('step', other, 1), 'beamslider:state', ...
    {'another scene'}, 'a state whose overrides were changed (another scene than its checkpoint''s)');

  % (e) an edited scene file is seen by the next call (the scene cache checks
  % the file's bytes): the state made on the old contents is refused
  edited = fullfile(tmp, 'edited.ini');
  write_scene(edited, scene, 120);
  st = beamslider_sim('init', edited);
  st = beamslider_sim('step', st, 10);
  write_scene(edited, scene, 121);
  failed = failed + check_error(@() beamslider_sim('step', st, 10), 'beamslider:state', ...
    {'another scene'}, 'a state whose scene file was edited since init');
  write_scene(edited, scene, 120);
  info = beamslider_sim('info', beamslider_sim('step', st, 10));
  failed = failed + check(info.steps == 20 && info.frequency == 120, ...
    'the same state taken again once the file says what it said');

  if failed > 0
    error('check_octave: %d checks failed (%s)', failed, precision);
  end
  fprintf('check_octave: all checks passed (%s)\n', precision);
end

% A scene file: fig6 (base) at frequency [Hz].
function write_scene(path, base, frequency)
  fid = fopen(path, 'w');
  fprintf(fid, '[scene]\nbase = %s\n[excitation]\nfrequency = %g\n', base, frequency);
  fclose(fid);
end

function failed = check(ok, what)
  if ok
    fprintf('ok   - octave: %s\n', what);
    failed = 0;
  else
    fprintf('FAIL - octave: %s\n', what);
    failed = 1;
  end
end

% The call raises the error id with every text of needles in its message.
function failed = check_error(call, id, needles, what)
  try
    call();
    failed = check(false, [what ': no error']);
    return;
  catch e
    ok = strcmp(e.identifier, id);
    for k = 1:numel(needles)
      ok = ok && ~isempty(strfind(e.message, needles{k}));
    end
    failed = check(ok, sprintf('%s: %s: %s', what, e.identifier, e.message));
  end
end
