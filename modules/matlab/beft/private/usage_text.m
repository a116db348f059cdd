function text = usage_text(expert)
% --help: what the expert does and the options it takes.
  text = sprintf(['usage: %s [--help] [--interface] [--url URL] [--name NAME] [--param NAME=VALUE]...\n' ...
                  '       [--heartbeat-period S] [--ready-timeout S] [--connect-timeout S] [--resume-log LOG]\n\n' ...
                  '%s\n\nRuns through the run''s bridge (beft-bridge): it connects to --url, announces itself, ' ...
                  'and fires when the arbiter sends FIRE tokens addressed to its --name.\n\noptions:\n'], ...
                 expert.name, expert.description);
  rows = {'-h, --help', 'show this help message and exit'
          '--interface', 'print the channels read and written, and the parameters'
          '--url URL', 'the bridge''s WebSocket URL (env BEFT_BRIDGE_URL; default ws://127.0.0.1:8765)'
          '--lcm-url URL', 'accepted and unused: the bridge publishes on the run''s LCM'
          '--name NAME', sprintf('process name the arbiter fires (default %s)', expert.name)
          '--param NAME=VALUE', 'parameter NAME=VALUE (repeatable; see --interface)'
          '--heartbeat-period S', 'seconds between heartbeats (default 0.5)'
          '--ready-timeout S', 'longest wait for a firing''s inputs before firing without them [s]; 0: never'
          '--connect-timeout S', 'how long to try to reach the bridge at start [s] (default 30)'
          '--resume-log LOG', ['restarted after a crash: the run''s LCM log, from which the bridge sends the ' ...
                               'run''s history to rebuild this expert''s state; the launcher passes it']};
  for i = 1:size(rows, 1)
    text = [text sprintf('  %-22s %s\n', rows{i, :})]; %#ok<AGROW>
  end
  parameters = parameter_lines(expert.parameters);
  if ~isempty(parameters)
    text = [text sprintf('\nparameters (--param NAME=VALUE):\n') parameters];
  end
end
