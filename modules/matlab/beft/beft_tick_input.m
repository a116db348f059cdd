function expert = beft_tick_input(expert, channel, type, capacity)
%BEFT_TICK_INPUT  Reads CHANNEL (of beft TYPE), kept by the tick its messages belong to.
%   expert = beft_tick_input(expert, 'ROBOT_STATE', 'beft.robot_state_t');
%   A firing of tick k waits until this channel's message of tick k is
%   here; fire gets it as inputs.ROBOT_STATE. The newest CAPACITY messages
%   are kept (default 16), as the C++ TickInput does.
  if nargin < 4
    capacity = 16;
  end
  expert.inputs(end + 1) = struct('channel', channel, 'type', type, 'kind', 'tick', 'capacity', capacity, ...
                                  'optional', false);
end
