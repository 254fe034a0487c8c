function r = beamslider_run(scene, varargin)
% BEAMSLIDER_RUN  Run a beamslider scene, as `beamslider run` does.
%
%   r = beamslider_run(SCENE)
%   r = beamslider_run(SCENE, 't_end', 60, 'set', {'excitation.frequency', 120})
%
% SCENE is a scene file (configs/*.ini). Options, as name/value pairs:
%   't_end', T    run length [s]             ([run] t_end, like --t-end)
%   's0', S       start position x_C / L     ([run] s0)
%   'dt', DT      time step [s]              ([numerics] dt)
%   'model', M    'free' or 'pcs'            ([run] model)
%   'set', {'section.key', value, ...}       any field (beamslider fields), like --set
%   'every', N    a row of the series every N steps (default: every
%                 millisecond of simulated time, round(1e-3 / dt) steps)
%
% r holds the time series as column vectors from t = 0 (the columns of
% `beamslider run --out`): t [s], w_sensor (the deflection w(4L/7) [m]),
% s (x_C / L), z_r [m], beta [rad], contacts, pgs_iters, pgs_residual, and
% with a transducer v [V], p [W], v_s [V]; r.periods, one row per
% excitation period (t, amp_h, s, ds: `run --periods`); r.summary, the
% figures of the CLI's JSON summary (s_final, s_min, t_s_min, amp_final_h,
% hash, ...). The run is the CLI's, step for step: r.summary.hash equals
% the "hash" `beamslider run` prints for the same scene and overrides.
%
% Errors: beamslider:input (the message names the file and line or the
% override, the field, the value and the allowed range), beamslider:failed
% (the run stopped), beamslider:usage (a bad argument). See docs/octave.md.
  try
    r = beamslider_mex('run', scene, varargin{:});
  catch err
    % Octave puts the gateway's name before the library's message
    error(err.identifier, '%s', regexprep(err.message, '^beamslider_mex: ', ''));
  end
end
