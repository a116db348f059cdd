function expert = beft_output(expert, channel, type)
%BEFT_OUTPUT  Writes CHANNEL (of beft TYPE): fire returns its messages as outputs.(CHANNEL).
%   expert = beft_output(expert, 'GEOMETRY', 'beft.geometry_percepts_t');
  expert.outputs(end + 1) = struct('channel', channel, 'type', type);
end
