% Runs an expert from Octave's command line, as a program of the run:
%
%   octave-cli --quiet --no-history modules/matlab/run_expert.m EXPERT.m [OPTIONS]
%
% EXPERT.m is a function file whose function returns the expert
% (beft_expert ...); the options are beft_run_expert's, and Octave exits
% with its status. A script, because Octave 7 runs a function file given
% on its command line only when it lies in the current folder. MATLAB has
% no argv(): there, call beft_run_expert(EXPERT(), OPTIONS...) (README.md).
args = argv();
if isempty(args)
  fprintf(2, 'usage: octave-cli --quiet --no-history run_expert.m EXPERT.m [OPTIONS]\n');
  exit(2);
end
% A supervised process is stopped with SIGTERM: Octave would first write
% its workspace to octave-workspace in the current folder.
sigterm_dumps_octave_core(false);
sighup_dumps_octave_core(false);
crash_dumps_octave_core(false);
[expert_folder, expert_function] = fileparts(args{1});
addpath(fullfile(fileparts(mfilename('fullpath')), 'beft'));
if ~isempty(expert_folder)
  addpath(expert_folder);
end
exit(beft_run_expert(feval(expert_function), args{2:end}));
