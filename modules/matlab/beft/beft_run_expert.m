function status = beft_run_expert(expert, varargin)
%BEFT_RUN_EXPERT  Runs an expert: its command line, then live through the run's bridge.
%   status = beft_run_expert(expert, '--url', 'ws://127.0.0.1:8765', '--name', 'geometry')
%   The options are the Python and C++ experts': --help, --interface,
%   --url (env BEFT_BRIDGE_URL), --name, --param NAME=VALUE (repeatable),
%   --heartbeat-period, --ready-timeout, --connect-timeout, --resume-log,
%   and --lcm-url (accepted, unused). Returns the exit status: 0 at the end
%   of the run, 1 when the bridge cannot be reached or goes away, 2 when
%   the command line or the start-up is wrong or the bridge refuses it.
%
%   From Octave's command line: run_expert.m in this folder's parent.
  status = run_command_line(expert, varargin);
end

function status = run_command_line(expert, args)
  status = 2;
  try
    options = parse_options(expert, args);
  catch err
    fprintf(2, '%s: error: %s (see --help)\n', expert.name, err.message);
    return;
  end
  if options.help
    fprintf('%s', usage_text(expert));
    status = 0;
    return;
  end
  if options.interface
    fprintf('%s', interface_text(expert, options.name));
    status = 0;
    return;
  end
  try
    expert.parameters = set_parameters(expert.parameters, options.param);
  catch err
    fprintf(2, 'start-up failed: %s\n', err.message);
    return;
  end
  try
    status = live_session(expert, options);
  catch err
    if ~strcmp(err.identifier, 'beft:java')
      rethrow(err);  % a fault here: the process ends (1) and is restarted
    end
    fprintf(2, '%s: %s\n', options.name, err.message);
  end
end
