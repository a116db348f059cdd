function ports = input_stores(inputs)
% The expert's inputs, each with the messages kept for it: in arrival
% order, with their utime and tick.
  ports = inputs;
  [ports.messages] = deal({});
  [ports.utimes] = deal([]);
  [ports.ticks] = deal([]);
end
