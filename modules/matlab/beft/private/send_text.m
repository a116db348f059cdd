function send_text(s, topic, text)
% Publishes a message's JSON text on one of the client's channels (a
% client message publish frame on the channel's id).
  s.socket.publish(find(strcmp(s.client_topics, topic), 1), text);
end
