function history = history_events(socket)
% The run's history the bridge sent this resuming expert (its FIREs and
% DONEs and the channels it reads, from the run's log), as rows
% {channel, message} in log order: beft.BridgeSocket kept it aside and
% gives it as one JSON array, decoded at once.
  socket.takeHistory();
  events = beft_json_decode(char(socket.text()), char(socket.hex()));
  if isempty(events)
    history = cell(0, 2);
    return;
  end
  if isstruct(events)
    events = num2cell(events);
  end
  history = [cellfun(@(e) e.channel, events(:), 'UniformOutput', false), ...
             cellfun(@(e) e.message, events(:), 'UniformOutput', false)];
end
