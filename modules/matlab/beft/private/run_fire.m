function [outputs, failure, state] = run_fire(expert, firing, ports, parameters, state)
% Calls the expert's fire with the inputs of the firing's tick: its
% outputs as a cell of {channel, message} in the order returned, and why
% it failed ('' if it did not). An error raised by fire is a failure, its
% outputs then none.
  outputs = {};
  try
    inputs = inputs_of_tick(ports, firing.tick);
    [returned, failure, new_state] = expert.fire(firing, inputs, parameters, state);
    if isempty(failure)
      failure = '';
    end
    [outputs, undeclared] = output_list(returned, {expert.outputs.channel});
    state = new_state;
    if ~isempty(undeclared)
      failure = sprintf('publish on %s, which the expert does not declare', undeclared);
      outputs = {};
    end
  catch err
    failure = ['exception: ' err.message];
  end
end

function [outputs, undeclared] = output_list(returned, declared)
  outputs = {};
  undeclared = '';
  if isempty(returned)
    return;
  end
  channels = fieldnames(returned);
  for i = 1:numel(channels)
    if ~any(strcmp(declared, channels{i}))
      undeclared = channels{i};
      return;
    end
    messages = returned.(channels{i});
    if ~iscell(messages)
      messages = {messages};
    end
    for k = 1:numel(messages)
      outputs(end + 1, :) = {channels{i}, messages{k}}; %#ok<AGROW>
    end
  end
end
