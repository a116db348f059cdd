function [ports, stored] = store_message(ports, channel, message)
% Keeps a message heard on CHANNEL in the port that reads it (the newest
% `capacity`); stored is false when no port reads the channel.
  i = find(strcmp({ports.channel}, channel), 1);
  stored = ~isempty(i);
  if ~stored
    return;
  end
  tick = NaN;
  if isfield(message, 'tick')
    tick = message.tick;
  end
  ports(i).messages{end + 1} = message;
  ports(i).utimes(end + 1) = message.utime;
  ports(i).ticks(end + 1) = tick;
  drop = numel(ports(i).messages) - max(1, ports(i).capacity);
  if drop > 0
    ports(i).messages(1:drop) = [];
    ports(i).utimes(1:drop) = [];
    ports(i).ticks(1:drop) = [];
  end
end
