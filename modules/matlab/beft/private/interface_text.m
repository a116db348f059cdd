function text = interface_text(expert, process_name)
% --interface: the channels read and written and the parameters, in the
% C++ experts' words (lib/expert/run_expert.cpp).
  lines = {['process: ' process_name], 'reads:'};
  for i = 1:numel(expert.inputs)
    lines{end + 1} = sprintf('  %s  (%s)', expert.inputs(i).channel, expert.inputs(i).type); %#ok<AGROW>
  end
  lines = [lines, {sprintf('  FIRE  (beft.fire_t, tokens addressed to %s)', process_name), ...
                   '  RUN_STATUS  (beft.run_status_t, stops at the end of the run)', 'writes:'}];
  for i = 1:numel(expert.outputs)
    lines{end + 1} = sprintf('  %s  (%s)', expert.outputs(i).channel, expert.outputs(i).type); %#ok<AGROW>
  end
  lines = [lines, {'  DONE  (beft.done_t)', '  HEARTBEAT  (beft.heartbeat_t)'}];
  text = sprintf('%s\n', lines{:});
  parameters = parameter_lines(expert.parameters);
  if ~isempty(parameters)
    text = [text sprintf('parameters (--param NAME=VALUE):\n') parameters];
  end
end
