function expert = beft_latest_input(expert, channel, type)
%BEFT_LATEST_INPUT  Reads CHANNEL (of beft TYPE) for its newest message, whatever its tick.
%   expert = beft_latest_input(expert, 'TASK_STACK', 'beft.task_stack_t');
%   fire gets the newest message heard as inputs.TASK_STACK ([] before the
%   first); a firing never waits for it.
  expert.inputs(end + 1) = struct('channel', channel, 'type', type, 'kind', 'latest', 'capacity', 1, ...
                                  'optional', true);
end
