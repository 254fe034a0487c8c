function varargout = beamslider_sim(command, varargin)
% BEAMSLIDER_SIM  Step a beamslider simulator whose state is a uint8 array.
%
%   st = beamslider_sim('init', SCENE, options...)
%   [st, out] = beamslider_sim('step', st, n [, every])
%   [st, out] = beamslider_sim('step_measured', st, accel [, every])
%   st = beamslider_sim('excite', st, frequency, amplitude)
%   info = beamslider_sim('info', st)
%   [w, slope] = beamslider_sim('beam', st, x)
%
% 'init' starts a sim on SCENE (a scene file) with the options of
% beamslider_run ('t_end', 's0', 'dt', 'model', 'set'), at rest, in the
% model and at the s0 the scene gives. st is a uint8 column: the core's
% checkpoint, the scene file's absolute path and the overrides. It holds
% no pointer: it survives `clear beamslider_mex` (or `clear mex` in MATLAB),
% saves to a .mat file, and each copy
% is a sim of its own. Every call rebuilds the sim from st (the scene is
% kept between calls while it stays the same) and returns a new st; the
% scene file must still say what it said at 'init' (its hash is checked).
%
% 'step' takes n steps under the harmonic excitation (the scene's, or the
% last 'excite'); 'step_measured' one step per element of accel, the mean
% base acceleration over that step [m/s^2] (a measured record). out holds
% the series every `every` steps (default 1) after the first step, with the
% columns of beamslider_run (t, w_sensor, s, z_r, beta, contacts, pgs_iters,
% pgs_residual; v, p, v_s with a transducer); without a second output
% nothing is recorded. 'excite' sets the frequency [Hz] and amplitude
% [m/s^2] from the next step on, the phase going on. 'info' gives t, steps,
% s, w_sensor, z_r, beta, phase, frequency, amplitude, mu, e_n and the state
% hash (the "hash" of `beamslider run` after as many steps). 'beam' gives
% the deflection w(x) [m] and slope at positions x [m].
%
% A scene with an [excitation] schedule is refused (beamslider_run runs
% it). Errors as beamslider_run's, and beamslider:state for an array that
% is not a state of this build. See docs/octave.md.
  try
    [varargout{1:max(nargout, 1)}] = beamslider_mex('sim', command, varargin{:});
  catch err
    % Octave puts the gateway's name before the library's message
    error(err.identifier, '%s', regexprep(err.message, '^beamslider_mex: ', ''));
  end
end
